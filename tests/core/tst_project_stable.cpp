// SPDX-License-Identifier: GPL-3.0-or-later
// Project files written stably (issue 35): a file that is read and saved again comes back byte
// for byte; keys keep the order the file had, a grid typed as "0.70:1.15:0.05" stays that
// string, and a 1-DOF project gets no planar block. Also the unit system a project names.

#include "core/base/UnitSystem.h"
#include "core/io/Project.h"

#include <QtTest>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace kinstab;
namespace fs = std::filesystem;

namespace {

std::string fileText(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::vector<fs::path> shippedProjects() {
    std::vector<fs::path> out;
    for (const auto& e :
         fs::directory_iterator(fs::path(KINSTAB_SOURCE_DIR) / "resources/examples"))
        if (e.path().extension() == ".json" &&
            fileText(e.path()).find("\"kinstab-project\"") != std::string::npos)
            out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
}

// The first line where a and b differ, for the failure message.
std::string firstDifference(const std::string& a, const std::string& b) {
    std::istringstream x(a), y(b);
    std::string l, m;
    for (int n = 1;; ++n) {
        const bool gx = static_cast<bool>(std::getline(x, l)),
                   gy = static_cast<bool>(std::getline(y, m));
        if (!gx && !gy) return "same lines";
        if (!gx || !gy || l != m)
            return "line " + std::to_string(n) + ": file <" + l + "> saved <" + m + ">";
    }
}

const char* kShuffled = R"({
  "version": 1,
  "format": "kinstab-project",
  "model": "slab1d",
  "grid": {
    "frequencies": "0.5:1.125:0.125",
    "amplitudes": "0.70:1.15:0.05"
  },
  "building": {
    "unit": "m",
    "stories": 3,
    "height": 10.5,
    "plan_dimension": 12.0
  },
  "name": "shuffled"
})";

} // namespace

class TestProjectStable : public QObject {
    Q_OBJECT
private slots:
    void everyExampleSavesAsItWasRead() {
        const std::vector<fs::path> files = shippedProjects();
        QCOMPARE_GE(files.size(), std::size_t(6)); // the six under File → Open example
        std::string problems;
        for (const fs::path& f : files) {
            const std::string text = fileText(f);
            const Project p = loadProject(f.string());
            const std::string saved = projectText(p, f.parent_path().string());
            if (saved != text)
                problems += f.filename().string() + ": " + firstDifference(text, saved) + "\n";
        }
        QVERIFY2(problems.empty(), problems.c_str());
    }

    void keyOrderAndGridStringsAreKept() {
        Project p = parseProject(kShuffled);
        const std::string saved = projectText(p);
        // The file's order: version before format, model before grid, frequencies first.
        QVERIFY(saved.find("\"version\"") < saved.find("\"format\""));
        QVERIFY(saved.find("\"model\"") < saved.find("\"grid\""));
        QVERIFY(saved.find("\"frequencies\"") < saved.find("\"amplitudes\""));
        QVERIFY(saved.find("\"unit\": \"m\",\n    \"stories\": 3") != std::string::npos);
        // As typed, not 0.7, 0.75, 0.7999999999999999, ...
        QVERIFY(saved.find("\"amplitudes\": \"0.70:1.15:0.05\"") != std::string::npos);
        QVERIFY(saved.find("0.7999999999999999") == std::string::npos);
        // Keys the file did not have come after its own (slab, check: written by default).
        QVERIFY(saved.find("\"name\": \"shuffled\"") < saved.find("\"slab\""));
        // A changed grid is written as the numbers it now is.
        p.grid.amplitudes = {0.5, 1.0};
        const std::string changed = projectText(p);
        QVERIFY(changed.find("0.70:1.15:0.05") == std::string::npos);
        QVERIFY(changed.find("\"frequencies\": \"0.5:1.125:0.125\"") != std::string::npos);
    }

    void unusedBlocksAreLeftOut() {
        Project p = paperExampleProject();
        const std::string oneDof = projectText(p);
        QVERIFY(oneDof.find("\"planar\"") == std::string::npos);
        QVERIFY(oneDof.find("\"excitation\"") == std::string::npos);
        QVERIFY(oneDof.find("\"floors\"") == std::string::npos);
        p.model = ModelKind::Planar;
        QVERIFY(projectText(p).find("\"planar\"") != std::string::npos);
        // Planar inputs of its own are kept when the model goes back to 1-DOF.
        p.model = ModelKind::Slab1D;
        p.planar.fyHz *= 2.0;
        QVERIFY(projectText(p).find("\"planar\"") != std::string::npos);
        QCOMPARE(parseProject(projectText(p)).planar.fyHz, p.planar.fyHz);
    }

    void unitsAreTheProjectsOrItsBuildings() {
        Project p = paperExampleProject(); // a building in ft
        QVERIFY(projectUnits(p) == UnitSystem::US);
        p.building.unit = LengthUnit::Metres;
        QVERIFY(projectUnits(p) == UnitSystem::SI);
        p.units = UnitSystem::US;
        const Project back = parseProject(projectText(p));
        QVERIFY(back.units == UnitSystem::US);
        QVERIFY(projectText(p).find("\"units\": \"us\"") != std::string::npos);
        QVERIFY_THROWS_EXCEPTION(ProjectError, parseProject(R"({"format": "kinstab-project",
            "version": 1, "building": {}, "units": "imperial"})"));
    }

    void lengthsToTheMillimetreOrHundredthInch() {
        // t* = 0.099 s: d = 2 g t*² = 2 × 9.80665 × 0.099² = 0.192234 m.
        const double d = 2.0 * 9.80665 * 0.099 * 0.099;
        QCOMPARE(lengthText(d, UnitSystem::SI, LengthScale::Detail), std::string("192.2"));
        QCOMPARE(lengthText(d, UnitSystem::US, LengthScale::Detail), std::string("7.57"));
        // 150 mm stays 150 mm (the report printed 5.9 in); 7⅝ in = 193.675 mm.
        QCOMPARE(lengthText(0.150, UnitSystem::SI, LengthScale::Detail), std::string("150"));
        QCOMPARE(lengthText(7.625 * 0.0254, UnitSystem::SI, LengthScale::Detail),
                 std::string("193.7"));
        // 177 ft = 53.9496 m, to the millimetre.
        QCOMPARE(lengthText(177 * 0.3048, UnitSystem::SI, LengthScale::Structure),
                 std::string("53.95"));
        QCOMPARE(lengthText(177 * 0.3048, UnitSystem::US, LengthScale::Structure),
                 std::string("177"));
    }
};

QTEST_GUILESS_MAIN(TestProjectStable)
#include "tst_project_stable.moc"
