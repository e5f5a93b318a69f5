#include "app/cli/Args.h"
#include "app/cli/Commands.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

namespace kinstab::cli {

void writeOutput(const std::string& path, const std::string& text) {
    if (path.empty() || path == "-") {
        std::cout << text;
        std::cout.flush();
        return;
    }
    const std::string tmp = path + ".part";
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) throw UsageError("-o " + path + ": cannot write this file");
        out << text;
        if (!out.flush()) throw UsageError("-o " + path + ": write failed");
    }
    std::error_code ec;
    std::filesystem::rename(tmp, path, ec);
    if (ec) throw UsageError("-o " + path + ": " + ec.message());
}

} // namespace kinstab::cli
