// SPDX-License-Identifier: GPL-3.0-or-later
// codes: the building-code lateral force ratios of one building, with each coefficient's
// trail. The building and code inputs are the project file's objects ("building", "codes"), read
// by the core's own readers, so a bad field raises ValueError naming it ("building.stories ...").

#include "core/codes/CodeSet.h"
#include "core/io/CodesJson.h"
#include "python/src/Arguments.h"
#include "python/src/Bindings.h"

namespace py = pybind11;

namespace kinstab::python {

namespace {

// JSON text in, JSON text out: the package turns dicts into text and back (exact for floats).
std::string codesJson(const std::string& buildingText, const std::string& codesText) {
    try {
        const nlohmann::json b = nlohmann::json::parse(buildingText);
        const nlohmann::json c = nlohmann::json::parse(codesText);
        const Building building = buildingFromJson(JsonReader(b, "building"));
        const CodeSelection codes = codesFromJson(JsonReader(c, "codes"));
        if (codes.empty())
            badArgument("codes: no code selected (give ubc1976, atc306, ubc1997, "
                        "asce7_22 or ec8 inputs)");
        return codeResultsJson(runCodes(building, codes)).dump();
    } catch (const JsonFieldError& e) {
        badArgument(e.what());
    } catch (const InputError& e) {
        badArgument(e.what());
    }
}

} // namespace

void bindCodes(py::module_& m) {
    m.def("_codes_json", &codesJson, py::arg("building"), py::arg("codes"));
}

} // namespace kinstab::python
