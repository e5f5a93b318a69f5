// SPDX-License-Identifier: GPL-3.0-or-later
// Long for a reason (over 400 lines with its header): it is one table, every command's help text
// beside the others, with the flag blocks several commands share. Split per command, the shared
// blocks would have to live in a third place and the man page's list would be read from many.
#include "app/cli/HelpText.h"

#include <algorithm>

namespace kinstab::cli {

namespace {

// Flags shared by simulate, surface, critical and bench (defaults in brackets).
#define KINSTAB_MODEL_FLAGS                                                                        \
    "model flags:\n"                                                                               \
    "  --model slab1d|planar        the 1-DOF slab or the 2-DOF planar slab [slab1d]\n"            \
    "  --envelope fast|moderate|slow  Table 4 envelope preset [moderate]\n"                        \
    "  --alpha X --beta Y           a user envelope exp(-alpha t) - exp(-beta t), 1/s\n"           \
    "  --tstar S                    characteristic time t* = sqrt(d / 2g), s [0.099]\n"            \
    "  --wall-width-in D            wall width d, inches (gives t*; excludes --tstar)\n"           \
    "  --wall-width-mm D            wall width d, millimetres (excludes --tstar, "                 \
    "--wall-width-in)\n"                                                                           \
    "  --mu M                       friction coefficient [0.6]\n"                                  \
    "  --limit L                    bearing / (d/2): collapse when |delta| > L [1]\n"              \
    "  --duration TAU               stop the excitation at tau = TAU (dimensionless) [none]\n"     \
    "  --scale tau_max|tau_rise|tau_dur|one  tau_ref of gamma_c = tau_ref / tau_c [tau_max]\n"     \
    "  --solver exact|paper         event-driven closed form, or the 1980 RK4 [exact]\n"           \
    "  --paper-steps N              RK4 steps per period for --solver paper [16]\n"                \
    "planar only (--model planar):\n"                                                              \
    "  --fy F                       frequency along the walls, Hz (required)\n"                    \
    "  --ay-ratio R                 A_y / A_x [0.9]\n"                                             \
    "  --theta X                    2 wall length / wall width: limit along the walls [20]\n"      \
    "  --vertical FILE              vertical record, normal force 1 + a_z [none: gravity]\n"       \
    "  --normalization product|envelope  S_max of envelope x sine, or envelope alone [product]\n"

#define KINSTAB_RECORD_FLAGS                                                                       \
    "record flags:\n"                                                                              \
    "  --record-format auto|at2|cosmos|csmip|values|time-accel  file format [auto]\n"              \
    "  --record-dt S                sample step, s (needed by --record-format values)\n"           \
    "  --record-unit g|m/s2|cm/s2|ft/s2|in/s2  unit of the values [from the file, else g]\n"       \
    "  --record-channel N|NAME      channel of a multi-channel file [the first]\n"                 \
    "  --floor-period T             floor filter: oscillator period, s [none: ground motion]\n"    \
    "  --damping Z                  floor filter damping ratio [0.02]\n"

const char* kSimulate =
    "usage: kinstab-cli simulate --amplitude A --frequency F [model flags] [--history FILE.csv]\n"
    "                            [--history-step DTAU] [--events]\n"
    "       kinstab-cli simulate --record FILE [--amplitude PEAK_G | --scale-factor K]\n"
    "                            [record flags] [model flags] [--critical [search flags]]\n"
    "One run of the slab; prints a JSON object (outcome, tau_c, gamma_c, slip_intervals,\n"
    "max_abs_delta, residual_delta, work, wall_time_s).\n"
    "  --amplitude A                peak floor acceleration, g (with --record: target peak);\n"
    "                               above 4 g a warning: m/s² typed as g? (1 g = 9.80665 m/s²)\n"
    "  --frequency F                excitation frequency, Hz\n"
    "  --history FILE.csv           write the sampled history (tau, a, delta, velocity, state)\n"
    "  --history-step DTAU          history sample step, dimensionless time [0.05]\n"
    "  --events                     list every stick/slip event in the JSON\n"
    "  --record FILE                drive the slab with an accelerogram instead of the sine\n"
    "  --scale-factor K             multiply the record by K [1]\n"
    "  --record-y FILE              planar: the record along the walls\n"
    "  --critical                   with --record: search the critical scale of the record\n"
    "search flags: --max-amplitude A [5] --scan-step S [0.01] --tolerance T [1e-6] "
    "(g)\n" KINSTAB_MODEL_FLAGS KINSTAB_RECORD_FLAGS;

const char* kSurface =
    "usage: kinstab-cli surface --amplitudes LIST --frequencies LIST [model flags] [--threads N]\n"
    "                           [--format json|csv|table] [-o FILE]\n"
    "The gamma_c(A, f) surface: one run per grid point.\n"
    "  --amplitudes LIST            peak accelerations, g (a,b,c or start:stop:step); a warning\n"
    "                               when every one is above 4 g (m/s² typed as g?)\n"
    "  --frequencies LIST           frequencies, Hz\n"
    "  --threads N                  worker threads, 0 = all cores [0]\n"
    "  --format json|csv|table      output format [json]\n"
    "  -o FILE                      write to FILE (atomically) instead of standard "
    "output\n" KINSTAB_MODEL_FLAGS;

const char* kCritical =
    "usage: kinstab-cli critical --frequencies LIST [model flags] [--max-amplitude A]\n"
    "                            [--scan-step S] [--tolerance T]\n"
    "The critical amplitude A_crit(f), the smallest A that collapses; null when nothing up to\n"
    "--max-amplitude does.\n"
    "  --frequencies LIST           frequencies, Hz (a,b,c or start:stop:step)\n"
    "  --max-amplitude A            top of the search, g [5]\n"
    "  --scan-step S                scan step before refinement, g [0.01]\n"
    "  --tolerance T                refinement tolerance, g [1e-6]\n" KINSTAB_MODEL_FLAGS;

const char* kPrecision =
    "usage: kinstab-cli precision [-o FILE.csv] [--repeats N] [--no-regularized]\n"
    "Work-precision study: tau_c error against run time for each solver and setting.\n"
    "  -o FILE.csv                  also write the table as CSV\n"
    "  --repeats N                  timing repeats, the minimum is kept [5]\n"
    "  --no-regularized             leave out the regularized-friction variants\n";

const char* kBench =
    "usage: kinstab-cli bench [--repeats N] [--threads N] [--amplitudes LIST --frequencies LIST]\n"
    "                         [--vector-state] [model flags]\n"
    "       kinstab-cli bench --study FILE.json [--threads N] [--repeats N]\n"
    "       kinstab-cli bench --rocking [--map-points N] [--repeats N] [--threads N]\n"
    "Times the exact and the paper solver on one grid; prints JSON (min and median seconds),\n"
    "with the exact solver's CPU per point, events per point and evaluations per event.\n"
    "  --vector-state               instead: the exact solver with and without clearing the\n"
    "                               upper AVX state (vzeroupper) at each solver start\n"
    "  --study FILE                 instead: the study's cases on 1 and on --threads threads\n"
    "                               (cases per CPU-second, speed-up; [the allowed CPUs])\n"
    "  --rocking                    instead: the free-standing block, one pulse run and the\n"
    "                               N x N one-sine overturning map, linearised and exact\n"
    "  --map-points N               points per axis of that map [257]\n"
    "  --repeats N                  timed repeats [5]\n"
    "  --threads N                  worker threads, 0 = all cores [0]\n"
    "  --amplitudes LIST            peak accelerations, g [a built-in grid]\n"
    "  --frequencies LIST           frequencies, Hz [a built-in grid]\n" KINSTAB_MODEL_FLAGS;

const char* kRecord =
    "usage: kinstab-cli record --file FILE [record flags] [--peaks N] [--spectrum-csv FILE]\n"
    "                          [--sa-period S]\n"
    "Reads an accelerogram and prints what was read: format, samples, dt, peak, its metrics\n"
    "(PGA, PGV, PGD, Arias intensity, D5-95, mean period, Sa) and with --floor-period the\n"
    "floor motion that a slab on that floor feels.\n"
    "  --file FILE                  the accelerogram (AT2, COSMOS, CSMIP V2, values, time-accel)\n"
    "  --peaks N                    list the N largest peaks [5]\n"
    "  --spectrum-csv FILE          write the Fourier amplitude spectra as "
    "CSV\n"
    "  --sa-period S                Sa(T, 5 %) at this period, s [the floor period, if "
    "given]\n" KINSTAB_RECORD_FLAGS;

const char* kCodes =
    "usage: kinstab-cli codes --project FILE\n"
    "       kinstab-cli codes building flags code flags\n"
    "Top-floor force ratio F_n / w_n of each selected code, with the trail of coefficients.\n"
    "building flags:\n"
    "  --stories N                  number of stories (1-300)\n"
    "  --height-ft H | --height-m H roof height h_n\n"
    "  --dimension-ft D | --dimension-m D  plan dimension parallel to the force\n"
    "  --period T                   fundamental period, s [each code's formula]\n"
    "  --system NAME                dual_frame_wall, steel_moment_frame, concrete_moment_frame,\n"
    "                               steel_eccentric_braced, shear_wall, braced_frame, other "
    "[other]\n"
    "  --occupancy NAME             standard, assembly, hazardous, essential [standard]\n"
    "  --weights LIST               story weights, bottom first [equal]\n"
    "  --story-heights LIST         story heights, bottom first [equal]\n"
    "code flags (a code is computed when its first flag is given):\n"
    "  UBC 1976   --zone 0-4 [4] --k-factor K [--importance I] [--site-period TS, s]\n"
    "  ATC 3-06   --av AV | --map-area 1-7 [7]; --aa AA --soil S1|S2|S3 [S2] --r R\n"
    "  UBC 1997   --ubc97-zone 1|2A|2B|3|4 [4] --ubc97-r R [--ubc97-soil SA..SE [SD]]\n"
    "             [--na N [1] --nv N [1]] [--ubc97-importance I]\n"
    "  ASCE 7-22  --sds S --sd1 S (g) --tl T (s) --asce-r R [--s1 S] [--site-class C [Default]]\n"
    "             [--risk-category 1-4 [2]] [--ie I]\n"
    "  EC8        --ag AGR (g) --ground A-E [C] --q Q [--spectrum-type 1|2 [1]]\n"
    "             [--importance-class 1-4 [2]] [--gamma-i G] [--beta B [0.2]] [--irregular]\n";

const char* kCheck =
    "usage: kinstab-cli check --project FILE [--format json|table]\n"
    "The project's assessment: every check it implies, each code's ratio against the critical\n"
    "amplitude of the project's model at 1/T (sine.CODE, planar.CODE), against the record's\n"
    "critical peak (record.CODE), and the floor checks at the slab's level (floors.CODE.LEVEL),\n"
    "each with demand, capacity, margin and verdict, and the governing check (smallest margin).\n"
    "  --project FILE               a kinstab project (.json), e.g. the shipped examples\n"
    "  --format json|table          JSON (\"assessment\"), or a table [table on a terminal]\n";

const char* kFriction =
    "usage: kinstab-cli friction --data FILE.csv [--bearing-area IN2] [--alpha 0|2] [--beta "
    "best|0|1/3]\n"
    "                            [--max-cp PSI] [--outlier-alpha A] [--outlier-min-runs N]\n"
    "                            [--keep-outliers] [-o FILE]\n"
    "Calibrates the friction law from masonry triplet tests (Furgerson 1980, ch. III).\n"
    "  --data FILE.csv              the triplet runs (shear force against displacement)\n"
    "  --bearing-area IN2           bearing area A_b, square inches [none: no mu_inf]\n"
    "  --alpha 0|2                  regression weight exponent [2]\n"
    "  --beta best|0|1/3            work exponent of xi [best]\n"
    "  --max-cp PSI                 leave out confining pressures above PSI [400]\n"
    "  --outlier-alpha A            significance of the outlier test [0.05]\n"
    "  --outlier-min-runs N         runs needed before the outlier test applies [5]\n"
    "  --keep-outliers              keep the runs the outlier test rejects\n"
    "  -o FILE                      write the JSON to FILE instead of standard output\n";

const char* kReport =
    "usage: kinstab-cli report --project FILE -o FILE.pdf [--page a4|letter] [--figure-grid N]\n"
    "                          [--sections LIST] [--units si|us]\n"
    "Writes the design-check report as PDF: title and signature blocks, verdict, inputs, code\n"
    "trails, figures. Run times go to the JSON printed on stdout.\n"
    "  --project FILE               a kinstab project (.json)\n"
    "  -o FILE.pdf                  the report to write\n"
    "  --page a4|letter             paper size [a4]\n"
    "  --figure-grid N              grid points per axis of the surface figure [41]\n"
    "  --units si|us                lengths in m and mm or in ft and in [the project's \"units\",\n"
    "                               else us for a building in ft, si for one in m]\n"
    "  --sections LIST              optional sections, comma-separated, or all [all]:\n"
    "                               assumptions, symbols, inputs, codes, excitation, record,\n"
    "                               floors, blocks, surface, check, study, numerics, references\n"
    "                               (blocks: when the project names free-standing blocks; the\n"
    "                               title block, the verdict and the signature block are\n"
    "                               always printed; study: when the project names a study)\n";

const char* kFloors =
    "usage: kinstab-cli floors --project FILE [--record FILE] [--stiffness uniform|weight]\n"
    "                          [--damping Z] [--slab-level N] [--history-csv FILE] "
    "[--no-critical]\n"
    "The building as a shear building (one level a degree of freedom, all modes): peak floor\n"
    "accelerations under a ground record, the ASCE 7-22 and EN 1998-1 floor demands per level,\n"
    "the critical PGA at which the slab on each level falls, and the verdicts at the slab's "
    "level.\n"
    "  --project FILE               a kinstab project (.json)\n"
    "  --record FILE                the ground record [the project's excitation.record]\n"
    "  --stiffness uniform|weight   storey stiffness profile [the project's, else uniform]\n"
    "  --damping Z                  modal damping ratio in every mode [0.05]\n"
    "  --slab-level N               level of the slab, 1 to the number of stories [the roof]\n"
    "  --history-csv FILE           write the floor accelerations of every level (g) as CSV\n"
    "  --no-critical                skip the critical PGA search per level\n"
    "  --record-format auto|at2|cosmos|csmip|values|time-accel  file format [auto]\n"
    "  --record-dt S                sample step, s (needed by --record-format values)\n"
    "  --record-unit g|m/s2|cm/s2|ft/s2|in/s2  unit of the values [from the file, else g]\n"
    "  --record-channel N|NAME      channel of a multi-channel file [the first]\n";

const char* kRocking =
    "usage: kinstab-cli rocking --half-width B --half-height H [block flags] EXCITATION\n"
    "                           [--critical [--max-amplitude G]] [--history FILE.csv]\n"
    "One run of a free-standing rigid block: rest, slide, rock, slide-rock or overturn. Prints\n"
    "JSON: outcome (rest|slides|rocks|slide-rock|overturns|leaves-base), max_theta_over_alpha,\n"
    "impact_times_s, overturn_time_s (null unless it overturns), sliding_displacement_m.\n"
    "block flags:\n"
    "  --half-width B               half-width b of the block, m (0.001-100)\n"
    "  --half-height H              half-height h of the block, m (0.001-100)\n"
    "  --restitution E              angular velocity kept at an impact, (0, 1]\n"
    "                               [Housner: 1 - 1.5 sin^2 alpha]\n"
    "  --linear                     linearised equations (slender blocks) [exact]\n"
    "  --mu M                       Coulomb friction at the base [none: it never slides]\n"
    "  --initial-tilt R             released from rest at theta0 = R alpha, 0 <= R < 1 [0]\n"
    "  --duration S                 stop at S seconds [when its fate is decided]\n"
    "EXCITATION, one of:\n"
    "  --pulse half-sine|one-sine|one-cosine|rectangular  a pulse from t = 0, with\n"
    "      --amplitude A_G          its amplitude, g (negative: the other direction)\n"
    "      --pulse-frequency F      its frequency f_p, Hz (sine shapes)\n"
    "      --pulse-duration S       its duration, s (rectangular)\n"
    "  --frequency F --amplitude A  the paper's enveloped sine, Hz and g, with\n"
    "      --envelope fast|moderate|slow or --alpha X --beta Y (1/s) [moderate]\n"
    "  --record FILE                an accelerogram [record flags], scaled by\n"
    "      --amplitude PEAK_G | --scale-factor K [as recorded]\n"
    "      --vertical FILE          its vertical component, g up: gravity becomes g (1 + a_v)\n"
    "      --project FILE --level N the motion of level N of the project's building under\n"
    "                               the record as ground motion (0: the ground)\n"
    "  none, with --initial-tilt    free rocking\n"
    "  --critical                   also the smallest overturning amplitude "
    "(critical_amplitude_g,\n"
    "                               null if none) and overturning_intervals_g [[from, to], ...]\n"
    "  --max-amplitude G            largest amplitude (record: peak) searched, g [5]\n"
    "  --scan-points N              amplitudes scanned before bisection [200]\n"
    "  --tolerance T                relative tolerance of each interval end [1e-4]\n"
    "  --refine-depth D             halve a gap between standing amplitudes where one rocked\n"
    "                               past 0.5 alpha, down to a scan step / 2^D [6]\n"
    "  --max-runs N                 runs of the whole search at most [5000]; reaching it is\n"
    "                               said on stderr and critical_run_limit_reached: true\n"
    "  --history FILE.csv           write t, theta, theta/alpha, omega, sliding, mode, a_h\n"
    "  --history-step S             its sample step, s [0.01]\n" KINSTAB_RECORD_FLAGS;

const char* kRockingMap =
    "usage: kinstab-cli rocking-map --half-width B --half-height H [--restitution E] [--linear]\n"
    "                               [--pulse SHAPE] [--amplitudes MIN,MAX] [--frequencies "
    "MIN,MAX]\n"
    "                               [--points N] [--threads N] [--format json|csv] [-o FILE]\n"
    "The overturning map of a pulse over a_p / (alpha g) and omega_p / p (Zhang & Makris 2001):\n"
    "per point survives (0), overturns (1) or leaves the base (2), and max theta / alpha.\n"
    "  --pulse SHAPE                half-sine|one-sine|one-cosine|rectangular [one-sine]\n"
    "                               (rectangular: duration 2 pi / omega_p)\n"
    "  --amplitudes MIN,MAX         a_p / (alpha g) [0.5,10]\n"
    "  --frequencies MIN,MAX        omega_p / p [0.5,10]\n"
    "  --points N                   points per axis [101]; --amplitude-points N,\n"
    "                               --frequency-points N for each\n"
    "  --threads N                  worker threads, 0 = all cores [0]\n"
    "  --format json|csv            the grid as JSON rows or one CSV line per point [json]\n"
    "  -o FILE                      output file [stdout]\n";

#undef KINSTAB_MODEL_FLAGS
#undef KINSTAB_RECORD_FLAGS

const char* kStudy =
    "usage: kinstab-cli study --spec FILE.json [-o FILE.jsonl] [--shard K/N] [--threads N]\n"
    "                         [--resume]\n"
    "       kinstab-cli study --spec FILE.json --count\n"
    "  --spec FILE                  the study: records x parameters (docs/studies.md)\n"
    "  -o FILE                      JSONL results, one row per case [stdout]\n"
    "  --shard K/N                  run only the cases whose index % N == K - 1 [1/1]\n"
    "  --threads N                  worker threads [the CPUs of this process's affinity]\n"
    "  --resume                     continue from the complete rows an interrupted run of\n"
    "                               this shard left in -o's temporary file; keep it if this\n"
    "                               run is interrupted too (needs -o FILE)\n"
    "  --count                      print the number of cases and stop\n";

const char* kMerge =
    "usage: kinstab-cli merge SHARD.jsonl... [--list FILE] -o FILE.jsonl\n"
    "  SHARD                        shard results of kinstab-cli study, any order, any\n"
    "                               number; refused when they are of different studies\n"
    "  --list FILE                  a file naming more shards, one per line\n"
    "  -o FILE                      the merged results, as one unsharded run writes them\n";

const char* kFragility =
    "usage: kinstab-cli fragility --results FILE.jsonl [--format json|csv] [--threads N]\n"
    "                             [-o FILE]\n"
    "  --results FILE               study results (JSONL), merged or one shard\n"
    "  --format json|csv            fit, bounds, points and curve; or one line per set [json]\n"
    "  --bootstrap N                bootstrap resamples over records for the bounds [1000]\n"
    "  --seed S                     bootstrap seed [1]\n"
    "  --level P                    two-sided confidence level of the bounds [0.9]\n"
    "  --threads N                  threads of the bootstrap (same bounds whatever N)\n"
    "                               [the CPUs of this process's affinity]\n"
    "  -o FILE                      output file [stdout]\n";

const char* kRisk =
    "usage: kinstab-cli risk --hazard FILE [--hazard-format auto|openquake|usgs|csv]\n"
    "                        [--site LON,LAT] (--results FILE.jsonl [--set K] | --median G\n"
    "                        --beta B | --beta B) [--years N] [--target-rate R] [--im G]\n"
    "  --hazard FILE                the site's hazard curve: OpenQuake hazard_curve CSV, USGS\n"
    "                               hazard JSON or a CSV im_g,annual_rate\n"
    "  --hazard-format F            auto|openquake|usgs|csv [auto: from the file's text]\n"
    "  --site LON,LAT               OpenQuake: the site's row, degrees [the first row]\n"
    "  --results FILE               study results (JSONL): the fragility of each parameter set\n"
    "  --set K                      only parameter set K of the results, with bootstrap\n"
    "                               percentiles [every set]\n"
    "  --median G                   a fragility's median, g (with --beta)\n"
    "  --beta B                     its dispersion; alone: the risk-targeted median for B\n"
    "  --measure M                  the fragility's measure: pga, sa(1s/5%), SA(1.0) [none]\n"
    "  --years N                    years of the probability of collapse [50]\n"
    "  --target-rate R              annual rate of collapse aimed at, per year\n"
    "                               [2.0101e-4: 1 % in 50 years, ASCE 7-22 ch. 21]\n"
    "  --im G                       an intensity, g (e.g. the site's MCE_R): P(collapse) there\n"
    "                               against the 10 % target\n"
    "  --bootstrap N                bootstrap resamples over records: percentiles [1000]\n"
    "  --seed S                     bootstrap seed [1]\n"
    "  -o FILE                      output file [stdout]\n";

} // namespace

const std::vector<CommandHelp>& commandHelps() {
    static const std::vector<CommandHelp> t = {
        {"simulate", "one run of the slab (enveloped sine or a record)", kSimulate},
        {"surface", "the gamma_c(A, f) surface over a grid", kSurface},
        {"critical", "the critical amplitude A_crit(f)", kCritical},
        {"codes", "code lateral force ratios F_n / w_n", kCodes},
        {"check", "the design check of a project", kCheck},
        {"report", "the design-check report as PDF", kReport},
        {"record", "read an accelerogram, peaks, spectra, floor motion", kRecord},
        {"friction", "calibrate the friction law from triplet tests", kFriction},
        {"precision", "work-precision study of the solvers", kPrecision},
        {"bench", "time the solvers on a grid", kBench},
        {"floors", "floor motions, floor demands and critical PGA per level", kFloors},
        {"study", "critical intensities of a record suite x parameters (JSONL)", kStudy},
        {"merge", "merge the shards of a study into one results file", kMerge},
        {"fragility", "lognormal collapse fragility from study results", kFragility},
        {"risk", "annual rate and probability of collapse from a hazard curve", kRisk},
        {"rocking", "a free-standing block: rocking, sliding, overturning", kRocking},
        {"rocking-map", "the overturning map of a block under a pulse", kRockingMap},
    };
    return t;
}

std::string usageText() {
    std::string s = "usage: kinstab-cli COMMAND [flags]\n"
                    "       kinstab-cli COMMAND --help\n"
                    "       kinstab-cli --version\n\ncommands:\n";
    for (const CommandHelp& c : commandHelps())
        s += "  " + std::string(c.name) +
             std::string(std::max<std::size_t>(
                             1, 11 - std::min<std::size_t>(11, std::string(c.name).size())),
                         ' ') +
             c.summary + "\n";
    s += "\nLIST: comma-separated numbers or start:stop:step.\n"
         "Exit codes: 0 success, 2 bad input (the message names the flag and value), 3 an output\n"
         "could not be written (full disk, closed stdout), 4 the model gave no finite result,\n"
         "1 a bug in kinstab. Every JSON output carries \"kinstab_version\".\n"
         "Manual: man kinstab-cli (installed), or from a build tree: man -l\n"
         "build/packaging/kinstab-cli.1.\n";
    return s;
}

std::string commandHelpText(const std::string& name) {
    for (const CommandHelp& c : commandHelps())
        if (name == c.name) return c.text;
    return {};
}

std::string versionText() {
    return "kinstab-cli " KINSTAB_VERSION "\n"
           "Licence GPL-3.0-or-later: this is free software; there is NO WARRANTY.\n";
}

} // namespace kinstab::cli
