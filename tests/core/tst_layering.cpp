// SPDX-License-Identifier: GPL-3.0-or-later
// Core's floors: a folder of core/ may include its own folder and the folders below it, never one
// above. The order is declared here, once (README "Layout" prints it); a new folder must be given
// its floor before the test passes. The checker is first tried on a small tree made for the test,
// with one include that runs back up, so a checker that finds nothing cannot pass. JSON text is
// io's: a folder below io computes values and includes no JSON library (the study's rows, its
// results files and the fragility text are written and read in io).

#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

// Bottom floor first. io/ reads and writes every file, the study file and the project's study
// included; risk/ reads hazard files and integrates a study's fragilities against them;
// assessment/ composes a project's checks from everything below, so it sits on top.
const std::vector<std::string> kCoreFloors = {
    "base",     "numerics",  "records", "codes", "friction",  "excitation",
    "slab",     "precision", "sweep",   "check", "building",  "rocking",
    "analysis", "study",     "io",      "risk",  "assessment"};

struct Finding {
    std::vector<std::string> upward;      // "core/a/X.h includes core/b/Y.h (floor b above a)"
    std::vector<std::string> undeclared;  // folders of the tree without a floor
    std::vector<std::string> jsonBelowIo; // "core/study/X.cpp includes <nlohmann/json.hpp>"
    int crossIncludes = 0;                // includes between two different folders
};

int floorOf(const std::string& folder) {
    const auto it = std::find(kCoreFloors.begin(), kCoreFloors.end(), folder);
    return it == kCoreFloors.end() ? -1 : int(it - kCoreFloors.begin());
}

void checkFile(const fs::path& file, const std::string& folder, Finding& out) {
    static const std::regex include(R"(^\s*#\s*include\s*"core/([^/"]+)/([^"]+)\")");
    static const std::regex json(R"(^\s*#\s*include\s*<(nlohmann/[^>]+)>)");
    std::ifstream in(file);
    std::string line;
    while (std::getline(in, line)) {
        std::smatch m;
        if (std::regex_search(line, m, json) && floorOf(folder) < floorOf("io"))
            out.jsonBelowIo.push_back("core/" + folder + "/" + file.filename().string() +
                                      " includes <" + m[1].str() + ">");
        if (!std::regex_search(line, m, include) || m[1] == folder) continue;
        ++out.crossIncludes;
        const std::string target = m[1];
        if (floorOf(target) > floorOf(folder) || floorOf(target) < 0)
            out.upward.push_back("core/" + folder + "/" + file.filename().string() +
                                 " includes core/" + target + "/" + m[2].str() + " (floor " +
                                 target + " is not below " + folder + ")");
    }
}

Finding checkCore(const fs::path& core) {
    Finding out;
    for (const auto& dir : fs::directory_iterator(core)) {
        if (!dir.is_directory()) continue;
        const std::string folder = dir.path().filename().string();
        if (floorOf(folder) < 0) {
            out.undeclared.push_back("core/" + folder);
            continue;
        }
        for (const auto& f : fs::recursive_directory_iterator(dir.path())) {
            const auto ext = f.path().extension();
            if (f.is_regular_file() && (ext == ".h" || ext == ".cpp"))
                checkFile(f.path(), folder, out);
        }
    }
    return out;
}

void writeFile(const fs::path& p, const std::string& text) {
    fs::create_directories(p.parent_path());
    std::ofstream(p) << text;
}

QString joined(const std::vector<std::string>& lines) {
    std::string s;
    for (const auto& l : lines)
        s += "\n  " + l;
    return QString::fromStdString(s);
}

} // namespace

class TestLayering : public QObject {
    Q_OBJECT
private slots:
    // A tree made for the test: slab/ including sweep/ runs back up; sweep/ including slab/ and
    // a comment naming sweep/ do not; a folder with no floor is reported; study/ including the
    // JSON library is, io/ including it is not.
    void checkerFindsAnUpwardInclude() {
        QTemporaryDir tmp;
        QVERIFY(tmp.isValid());
        const fs::path core = fs::path(tmp.path().toStdString()) / "core";
        writeFile(core / "slab/A.h", "#pragma once\n#include \"core/sweep/B.h\"\n");
        writeFile(core / "sweep/B.cpp", "// see core/sweep/B.h\n#include \"core/slab/A.h\"\n");
        writeFile(core / "attic/C.h", "#pragma once\n");
        writeFile(core / "study/D.cpp", "#include <nlohmann/json.hpp>\n");
        writeFile(core / "io/E.cpp", "#include <nlohmann/json.hpp>\n");
        const Finding f = checkCore(core);
        QCOMPARE(f.crossIncludes, 2);
        QCOMPARE(f.upward.size(), std::size_t(1));
        QVERIFY(f.upward[0].find("core/slab/A.h includes core/sweep/B.h") == 0);
        QCOMPARE(f.undeclared, std::vector<std::string>{"core/attic"});
        QCOMPARE(f.jsonBelowIo,
                 std::vector<std::string>{"core/study/D.cpp includes <nlohmann/json.hpp>"});
    }

    void coreFoldersIncludeOnlyFloorsBelow() {
        const Finding f = checkCore(fs::path(KINSTAB_SOURCE_DIR) / "core");
        QVERIFY2(f.undeclared.empty(),
                 qPrintable("give these folders a floor in tst_layering.cpp and README's Layout:" +
                            joined(f.undeclared)));
        QVERIFY2(f.crossIncludes > 100, "the checker read too few includes: wrong source path?");
        QVERIFY2(f.upward.empty(), qPrintable("includes that run back up:" + joined(f.upward)));
        QVERIFY2(f.jsonBelowIo.empty(),
                 qPrintable("JSON below io (write it in core/io):" + joined(f.jsonBelowIo)));
    }
};

QTEST_GUILESS_MAIN(TestLayering)
#include "tst_layering.moc"
