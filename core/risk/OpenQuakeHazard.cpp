// SPDX-License-Identifier: GPL-3.0-or-later
// OpenQuake's hazard_curve-*.csv (core/risk/HazardFile.h). An example of the layout the engine
// writes (3.x):
//   #,,,,"generated_by='OpenQuake engine 3.16', ..., kind='mean', investigation_time=50.0,
//   imt='PGA'" lon,lat,depth,poe-0.005,poe-0.007,... -122.0,37.0,0.0,0.99,0.97,...
// Older versions leave out the depth column; it is optional here.

#include "core/base/InputLimits.h"
#include "core/base/TextInput.h"
#include "core/friction/TripletCsv.h"
#include "core/risk/HazardReaders.h"

#include <cctype>
#include <cmath>
#include <limits>

namespace kinstab {

namespace {

// The value of key=VALUE in the banner: quoted ('...' or "...") or up to a comma or space.
std::optional<std::string> bannerValue(std::string_view banner, std::string_view key) {
    for (std::size_t at = banner.find(key); at != std::string_view::npos;
         at = banner.find(key, at + 1)) {
        const bool wordStart =
            at == 0 ||
            !(std::isalnum(static_cast<unsigned char>(banner[at - 1])) || banner[at - 1] == '_');
        const std::size_t v = at + key.size();
        if (!wordStart || v >= banner.size() || banner[v] != '=') continue;
        std::string_view rest = banner.substr(v + 1);
        if (!rest.empty() && (rest.front() == '\'' || rest.front() == '"')) {
            const std::size_t close = rest.find(rest.front(), 1);
            if (close == std::string_view::npos) return std::nullopt;
            return std::string(rest.substr(1, close - 1));
        }
        return std::string(rest.substr(0, rest.find_first_of(", \"'")));
    }
    return std::nullopt;
}

struct Banner {
    double investigationTime = 0; // years
    HazardMeasure measure;
};

Banner readBanner(std::string_view line, const std::string& where) {
    if (line.empty() || line.front() != '#')
        throw HazardError(where + ": an OpenQuake hazard curve starts with its banner line "
                                  "(# ... investigation_time=T, imt='...')");
    const auto t = bannerValue(line, "investigation_time");
    if (!t) throw HazardError(where + ": the banner has no investigation_time=");
    const std::optional<double> years = parseDouble(*t);
    if (!years || !std::isfinite(*years) || !(*years > 0.0))
        throw HazardError(where + ": investigation_time=" + quotedToken(*t) +
                          " must be a number of years > 0");
    const auto imt = bannerValue(line, "imt");
    if (!imt) throw HazardError(where + ": the banner has no imt='...'");
    const auto m = measureFromOpenQuake(*imt);
    if (!m)
        throw HazardError(where + ": unknown intensity measure imt=" + quotedToken(*imt) +
                          " (kinstab's fragilities are in g: PGA or SA(T))");
    return {*years, *m};
}

std::vector<std::string> fields(std::string_view line, const std::string& where) {
    try {
        return splitCsvLine(std::string(line));
    } catch (const std::invalid_argument& e) {
        throw HazardError(where + ": " + e.what());
    }
}

struct Columns {
    std::size_t first = 2;          // of the PoEs: after lon,lat[,depth]
    std::vector<std::string> names; // poe-X
    std::vector<double> imG;
};

Columns readHeader(std::string_view line, const std::string& where) {
    const std::vector<std::string> f = fields(line, where);
    if (f.size() < 3 || f[0] != "lon" || f[1] != "lat")
        throw HazardError(where + ": the header must be lon,lat[,depth],poe-X..., got " +
                          quotedToken(line));
    Columns c;
    c.first = f[2] == "depth" ? 3 : 2;
    if (f.size() - c.first > limits::kMaxHazardPoints)
        throw HazardError(where + ": more than the limit of " +
                          std::to_string(limits::kMaxHazardPoints) + " intensities");
    for (std::size_t k = c.first; k < f.size(); ++k) {
        if (f[k].rfind("poe-", 0) != 0)
            throw HazardError(where + ": column " + std::to_string(k + 1) + " " +
                              quotedToken(f[k]) + " is not poe-X (X the intensity in g)");
        c.names.push_back(f[k]);
        c.imG.push_back(hazardNumber(std::string_view(f[k]).substr(4), where, f[k]));
    }
    return c;
}

// The annual rate of a probability of exceedance in T years, Poisson: -ln(1 - PoE) / T.
double annualRate(double poe, double years, const std::string& where) {
    if (!std::isfinite(poe) || poe < 0.0)
        throw HazardError(where + ": PoE " + formatDouble(poe) + " must be a finite number >= 0");
    if (poe >= 1.0)
        throw HazardError(where + ": PoE " + formatDouble(poe) +
                          " is not below 1: the annual rate -ln(1 - PoE)/T would be infinite");
    return -std::log1p(-poe) / years;
}

} // namespace

HazardCurve parseOpenQuakeHazard(std::string_view text, const std::string& label,
                                 const HazardRequest& request) {
    TextLines cursor(text);
    std::string_view line;
    cursor.next(line);
    const Banner banner = readBanner(line, hazardLine(label, 1));
    checkHazardMeasure(banner.measure, request, hazardLine(label, 1));
    if (!cursor.next(line)) throw HazardError(label + ": no header line after the banner");
    const Columns cols = readHeader(line, hazardLine(label, 2));
    std::size_t sites = 0;
    double nearest = std::numeric_limits<double>::infinity();
    std::string nearestSite;
    while (cursor.next(line)) {
        if (line.find_first_not_of(" \t") == std::string_view::npos) continue;
        const std::string where = hazardLine(label, cursor.number());
        const std::vector<std::string> f = fields(line, where);
        if (f.size() != cols.first + cols.names.size())
            throw HazardError(where + ": " + std::to_string(f.size()) + " fields, the header has " +
                              std::to_string(cols.first + cols.names.size()));
        ++sites;
        const double lon = hazardNumber(f[0], where, "lon"), lat = hazardNumber(f[1], where, "lat");
        if (request.site) {
            const double d = std::hypot(lon - request.site->lon, lat - request.site->lat);
            if (d < nearest) nearest = d, nearestSite = formatDouble(lon) + "," + formatDouble(lat);
            if (!(d <= kHazardSiteToleranceDeg)) continue;
        }
        std::vector<HazardPoint> points;
        for (std::size_t k = 0; k < cols.names.size(); ++k) {
            const std::string at = where + ", column '" + cols.names[k] + "'";
            const double poe = hazardNumber(f[cols.first + k], where, cols.names[k]);
            points.push_back({cols.imG[k], annualRate(poe, banner.investigationTime, at)});
        }
        const std::string source = label + ", site " + formatDouble(lon) + "," + formatDouble(lat) +
                                   " (line " + std::to_string(cursor.number()) + ")";
        return hazardCurve(banner.measure, std::move(points), source, [&](std::size_t i) {
            return where + ", column '" + cols.names[i] + "'";
        });
    }
    if (!request.site) throw HazardError(label + ": no site rows after the header");
    static_assert(kHazardSiteToleranceDeg == 1e-4, "the message below names the tolerance");
    throw HazardError(label + ": no site within 0.0001 degrees of " +
                      formatDouble(request.site->lon) + "," + formatDouble(request.site->lat) +
                      " among its " + std::to_string(sites) + " sites" +
                      (sites > 0 ? "; the nearest is " + nearestSite : std::string()));
}

} // namespace kinstab
