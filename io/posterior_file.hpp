#pragma once
// posterior.csv, the posterior sample a calibration writes (one row per kept Gibbs iteration: the
// calibrated values, then tau, then design_index): its reader and its writer.
#include <cstddef>
#include <string>
#include <vector>

namespace dtwin {

/// A posterior sample as `twin calibrate` writes it (posterior.csv): θ columns, then tau, then
/// design_index; one row per kept Gibbs iteration.
struct PosteriorSample {
  std::string path;
  std::vector<std::string> names;          ///< θ column names (the calibrated parameters)
  std::vector<std::vector<double>> theta;  ///< one row per draw, names.size() values each
  std::vector<double> tau;                 ///< error precision [1/unit²], > 0
  std::vector<long> design_index;          ///< >= 0
  std::size_t size() const { return tau.size(); }
};

/// Reads and validates posterior.csv. Rules (InputError naming file:line, the column and the
/// rule): a header of at least one θ name, then `tau`, then `design_index`, names unique and
/// non-empty; every line has one field per column; θ values finite numbers; tau a finite number
/// > 0; design_index an integer >= 0; at least one row. CR line ends and blank lines are accepted.
/// A posterior.csv in a calibration's folder is also checked against the checksum its
/// summary.json records (checkPosteriorChecksum).
PosteriorSample readPosteriorCsv(const std::string& path);
/// InputError naming `path` when the summary.json beside it records a "posterior_checksum"
/// (common/checksum.hpp contentChecksum) that `text`, the file's bytes, does not have: a value
/// changed on disk after the calibration wrote it is refused, never used. No summary.json, or one
/// without the field (written before checksums were recorded): nothing to check.
void checkPosteriorChecksum(const std::string& path, const std::string& text);
/// The same from text; `name` prefixes errors.
PosteriorSample parsePosteriorCsv(const std::string& text, const std::string& name);

/// The text of posterior.csv (numbers round-trip exactly): the inverse of parsePosteriorCsv.
std::string posteriorCsv(const std::vector<std::string>& names,
                         const std::vector<std::vector<double>>& theta,
                         const std::vector<double>& tau, const std::vector<long>& design_index);

}  // namespace dtwin
