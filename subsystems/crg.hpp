#pragma once
// ASAM OpenCRG road surfaces (.crg): a regular grid of heights over the reference line's u
// (along) and v (across, left positive) coordinates. Read by our own parser, evaluated as the
// OpenCRG C API evaluates them with its default options (docs/measurements.md, "OpenCRG roads").
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "subsystems/road.hpp"

namespace dtwin {

/// A CRG file's road surface: heights z on the grid u_k = u0 + k du (k = 0..rows-1) times
/// v_j (the long sections, ascending: right to left), plus the reference line's elevation (the
/// integrated slope, REFERENCE_LINE_START_Z/END_Z) and banking per row.
struct CrgSurface {
  std::string name;      ///< the file, for messages and descriptions
  std::string format;    ///< the data format of $KD_Definition: LRFI, LDFI, KRBI, KDBI, LRBI, LDBI
  double u0_m = 0.0;     ///< REFERENCE_LINE_START_U (or the u channel's first value)
  double du_m = 0.0;     ///< REFERENCE_LINE_INCREMENT
  std::size_t rows = 0;  ///< cross sections
  std::vector<double> v_m;  ///< long-section positions, strictly ascending
  /// Heights of the long sections as the file gives them, row-major: z_m[k * v_m.size() + j].
  /// Missing ones (NaN) filled as the C API's default does: with the nearest valid height to the
  /// right (lower v) in the same cross section; right of the first valid one, with that one.
  std::vector<double> z_m;
  std::vector<double> ref_z_m;  ///< reference-line elevation per row (constant START_Z if no slope)
  std::vector<double> bank;     ///< banking [m/m] per row; empty: no banking
  std::size_t nan_filled = 0;   ///< NaNs filled at the borders of cross sections
  std::size_t nan_inside = 0;   ///< NaNs filled between valid heights of a cross section
  bool plan_geometry = false;   ///< a heading/x/y channel or a curved line (read, not used)
  /// Added to every height: minus the file's height at (u0, v_m.front()), the first cross
  /// section's rightmost point, which the C API's default modifiers put at z = 0 (REFPOINT_Z = 0,
  /// at REFPOINT_U_FRACTION = REFPOINT_V_FRACTION = 0).
  double z_offset_m = 0.0;

  double u1_m() const { return u0_m + du_m * static_cast<double>(rows - 1); }
  /// The file's height of long section j at cross section k (no reference line, no banking).
  double gridHeight(std::size_t k, std::size_t j) const { return z_m[k * v_m.size() + j]; }
  /// The C API's height at cross section k and lateral position v: linear in v between the long
  /// sections (the nearest one held outside them), plus the reference line's elevation, plus
  /// banking times v (v clamped to the long sections' range), plus z_offset_m.
  double nodeHeight(std::size_t k, double v) const;
  /// The C API's height at (u, v) (crgEvaluv2z, default options: BORDER_MODE_U = BORDER_MODE_V =
  /// 2, offsets 0, no smoothing; default modifiers: NaNs kept-last, reference point at z = 0):
  /// bilinear on the grid; outside the u range the first or last cross section is held, outside
  /// the v range the outermost long section.
  double height(double u, double v) const;
};

/// Parses the text of a CRG file; `name` (the file) prefixes every error. InputError, one line,
/// naming the file and the line or keyword, for anything outside the supported subset
/// (docs/measurements.md lists it).
CrgSurface parseCrg(const std::string& text, const std::string& name);
/// Reads and parses the file at `path` (InputError when it cannot be read).
CrgSurface readCrg(const std::string& path);

/// The two wheel tracks of a CRG surface as a road: the tracks run at lateral offsets left_v_m
/// and right_v_m along u, and road distance x = u - u_at_x0 (the u under x = 0). Sampled on the
/// file's own u increment with the C API's heights at the nodes (nodeHeight); between nodes the
/// GridRoad's C1 Hermite interpolant, which differs from the C API's (piecewise linear in u) by
/// at most 1/8 of the largest second difference of neighbouring node heights (stated in the
/// description as c1_vs_bilinear_bound_m).
std::shared_ptr<const GridRoad> makeCrgRoad(const CrgSurface& s, double left_v_m, double right_v_m,
                                            double u_at_x0, nlohmann::json description);

}  // namespace dtwin
