// Private to twin/: the simulator's recorder. It turns the knots the stepper recorded
// (twin/stepper.hpp) into a run's output: the trace on the output grid and the samples at the
// scenario's sample times, read from the cubic Hermite interpolant of the knots (the integrator's
// dense output), the tires' values there, and the sensors' channels with their loggers' filters.
#pragma once

#include <vector>

#include "twin/stepper.hpp"

namespace dtwin::sim {

class Recorder {
 public:
  Recorder(const VehicleSystem& sys, const SimulationOptions& opt) : sys_(sys), opt_(opt) {}

  /// Fills knot count, simulated time and the output trace of `res` from the recorded knots.
  void finish(const Knots& knots, const std::vector<double>& times, const ScenarioSpec& sc,
              RunResult& res) const;

  /// The output channels at the ascending times `ts` (within the knots' span), from the cubic
  /// Hermite interpolant of the knots: the integrator's dense output, whatever the times. The
  /// sensors unfiltered (their filters run on the output grid: makeOutput).
  void writeRows(const Knots& knots, const std::vector<double>& times, const ScenarioSpec& sc,
                 const std::vector<double>& ts, Trace& tr) const;

 private:
  /// The output grid (output_rate_hz) over the knots' span, the filtered sensors filtered.
  void makeOutput(const Knots& knots, const std::vector<double>& times, const ScenarioSpec& sc,
                  Trace& tr) const;
  using Knot = std::array<double, knot::KNOT>;
  /// Prescribed hubs: `st` set to the body's coordinates and auxiliary states interpolated between
  /// knots `a` and `b` (span h, fraction u) at time t, realised to accelerations.
  void rebuildState(State& st, double t, const Knot& a, const Knot& b, double h, double u) const;
  /// Whether a sensor of the model is filtered (its filter state lives on the output grid).
  bool filteredSensors() const;
  /// The filtered sensors' columns of a grid trace (makeOutput), filtered as the logger did.
  void filterSensors(Trace& grid) const;
  /// A filtered sensor at extra output times: the filtered grid column read there (its filter
  /// state lives on the grid; twin/trace.hpp GridSample, the four-point cubic).
  void resampleFilteredSensors(const Trace& grid, const std::vector<double>& ts,
                               Trace& samples) const;

  const VehicleSystem& sys_;
  const SimulationOptions& opt_;
};

}  // namespace dtwin::sim
