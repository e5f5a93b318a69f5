// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Every size limit on what kinstab reads, in one place, with the reason for its value. A file
// or flag beyond a limit is refused with a message naming the input and the limit, before any
// memory is reserved for it: a hostile or mistaken input must not exhaust the machine.

#include <cstddef>
#include <cstdint>

namespace kinstab::limits {

// Points of a γc surface (amplitudes × frequencies). A million points is a 1000 × 1000 grid,
// far finer than any chart can show; its results take about 100 MB as JSON.
inline constexpr std::size_t kMaxGridPoints = 1'000'000;

// Rows of a sampled history (simulate --history). Two million rows of five numbers are about
// 150 MB of CSV and 100 MB of memory; a finer step shows nothing a chart or a reader can use.
inline constexpr std::size_t kMaxHistoryRows = 2'000'000;

// Samples of one accelerogram. Ten million samples are 14 hours at 200 samples/s, longer
// than any strong-motion record; they take 80 MB as doubles.
inline constexpr std::size_t kMaxRecordSamples = 10'000'000;

// Bytes of a record file. Ten million values at up to 25 characters each, with headers.
inline constexpr std::uintmax_t kMaxRecordFileBytes = 256u * 1024u * 1024u;

// Bytes of a project or friction CSV file. Real ones are a few kilobytes; anything beyond
// 16 MB is not a project typed or saved by kinstab.
inline constexpr std::uintmax_t kMaxProjectFileBytes = 16u * 1024u * 1024u;
inline constexpr std::uintmax_t kMaxCsvFileBytes = 64u * 1024u * 1024u;

// Points of one hazard curve (core/risk). OpenQuake and the USGS tabulate 20 to 100 intensities;
// 10,000 is finer than any hazard calculation and keeps every integral over the curve instant.
inline constexpr std::size_t kMaxHazardPoints = 10'000;
// Bytes of a hazard file. An OpenQuake file holds one row per site: 64 MB is some 100,000 sites
// of 50 intensities, a regional run; one site's curve is a few kilobytes.
inline constexpr std::uintmax_t kMaxHazardFileBytes = 64u * 1024u * 1024u;
// Bytes of one row of study results (JSONL). A row is about 400 bytes; its longest text is the
// record's path as the study file writes it (at most PATH_MAX, 4096 bytes). 64 KiB leaves room
// for any row kinstab writes, yet a file without line breaks (/dev/zero, a binary file) is
// refused after 64 KiB instead of being held whole.
inline constexpr std::size_t kMaxResultsRowBytes = 64u * 1024u;

// Nesting of arrays and objects in a JSON document. A project nests four levels deep; 64
// leaves room for any future layout and keeps every recursive walk of the document shallow.
inline constexpr int kMaxJsonDepth = 64;

// Characters (Unicode code points, not bytes: core/base/DisplayText.h) of a name or title shown
// in a report, a chart or a message (project and building name, record name, station and
// component). Longer text is refused in a project and cut with "..." when it comes from a
// record header.
inline constexpr std::size_t kMaxNameChars = 200;
// Characters (code points) of a project's free-text description.
inline constexpr std::size_t kMaxDescriptionChars = 20'000;
// Revisions listed in a project's title block (ProjectInfo): a report's revision table fits one
// page; a project reissued more often keeps its older history elsewhere.
inline constexpr std::size_t kMaxRevisions = 50;
// Characters of a revision's mark ("0", "A", "P1", "C02"): it stands in the narrow first column
// of the revision table on page 1, which a longer text would stretch down the page.
inline constexpr std::size_t kMaxRevisionIdChars = 12;
// Characters of an offending token quoted in an error message.
inline constexpr std::size_t kMaxQuotedChars = 40;

// Sample interval of a record, s: 10 s is slower than any accelerograph, 0.1 ms (10,000
// samples/s) ten times faster than the fastest; outside that the DT is not a sample interval.
inline constexpr double kMaxRecordDt = 10.0;
inline constexpr double kMinRecordDt = 1e-4;
// Largest |acceleration| of a record sample, g. The largest recorded ground and floor motions
// are a few g; a value of hundreds of g is a file in other units read as g.
inline constexpr double kMaxRecordAccelG = 100.0;

// Largest amplitude, peak or search limit of a motion, g: of a grid, a single run, a record's
// target peak and the critical searches. A thousand g is far beyond any collapse of a slab on
// its walls (A_crit is a few g at most, Furgerson 1980, Fig. 26); a larger value is a typing slip.
inline constexpr double kMaxAmplitudeG = 1000.0;
// Widest wall a slab rests on, inches (t* from the wall width, Furgerson 1980, eq. 4.3): a
// thousand inches (25 m) is no wall.
inline constexpr double kMaxWallWidthIn = 1000.0;

} // namespace kinstab::limits
