#pragma once
// Bounded work: before a command starts, the work of each stage it will run is estimated from the
// study's sizes (simulations, simulated seconds, memory), and a command whose estimate exceeds the
// documented limits is refused with one line unless the user passes --force
// (docs/study-file.md, "Limits"). Per-value limits (a size, a step, a grid) are checked when the
// study file is read; these limits bound what the sizes multiply up to.
#include <string>
#include <vector>

#include "io/measurement.hpp"
#include "io/study.hpp"

namespace dtwin {

/// The estimated work of one stage of the method.
struct StageWork {
  std::string stage;        ///< "lab", "field", "calibrate M1", "synthesize M1", ...
  double simulations = 0;   ///< simulations run (an upper estimate)
  double simulated_s = 0;   ///< simulated seconds over all of them
  double memory_bytes = 0;  ///< the largest data the stage holds at once
};

/// The limits a command may not exceed without --force.
struct WorkLimits {
  double simulated_s = 2e7;   ///< ~4x the paper-size study (4.8e6 s): days on 2 cores
  double memory_bytes = 8e9;  ///< 8 GB
};

/// The stages of the whole method on `study` (`twin study`): lab, field, then calibrate and
/// synthesize per assembly. Upper estimates: every adaptive round is counted, and the optimiser and
/// the profile search at their budgets.
std::vector<StageWork> estimateStudyWork(const Study& study);

/// Upper estimate of the simulations of one calibration (calibration/calibrate.hpp) of
/// `parameters` parameters: its design (`design_points`: the first Latin hypercube and every
/// adaptive round), the multi-start optimiser and the profile search, at their budgets.
double calibrationSimulations(double design_points, double optimizer_starts, double parameters);

/// The simulated seconds one simulation of `data` needs: up to its last record's time.
double dataSpan(const LabData& data);

/// The stages of `all` named by one of `prefixes`: the whole name, or its first words ("calibrate"
/// takes every assembly's, "calibrate M1" only M1's).
std::vector<StageWork> selectStages(const std::vector<StageWork>& all,
                                    const std::vector<std::string>& prefixes);

/// InputError naming `where` (the study file) when the sum over `stages` exceeds `limits`, unless
/// `force`: "estimated work 3.1e+08 simulated s (calibrate M1 ...) exceeds the limit 2e+07 s; ...".
void checkWork(const std::vector<StageWork>& stages, const std::string& where, bool force,
               const WorkLimits& limits = {});

/// A size override (a command's `--runs`, `--lhs-points`, ...; <= 0: not given) into
/// study.sizes.<field>, checked against that size's limit; InputError naming `flag`.
void overrideSize(Study& study, const std::string& field, long value, const std::string& flag);
/// Refuses with an InputError naming the study file when the estimated work of the study's
/// `stages` (prefixes: "lab", "field", "calibrate", "calibrate M1", "synthesize", ...), times
/// `repeat`, exceeds the limits above, unless `force`.
void checkCommandWork(const Study& study, const std::vector<std::string>& stages, bool force,
                      double repeat = 1);

}  // namespace dtwin
