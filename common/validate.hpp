#pragma once
// The one convention for checking an options struct (docs/architecture.md, "Options").
//
// Every options struct has `void validate() const`, which throws InputError whose where() is
// "<options>.<field>" (e.g. "diagnose.effects") and whose rule says what was broken ("must be
// >= 1, got 0"). It is called once, at the library boundary (the public function that takes the
// struct). Library messages name fields, never command-line flags: the CLI maps a field to its
// flag (CommandHandle::field_flags, cli/commands.hpp), so that a user reads "--candidates: must be
// >= 1, got 0".
//
//   void DiagnoseOptions::validate() const {
//     const OptionCheck check("diagnose");
//     check.atLeast("candidates", candidates, 1);
//     check.open01("screen_alpha", screen_alpha);
//     check.require(!effects.empty(), "effects", "must name at least one effect");
//   }
#include <cmath>
#include <string>

#include "common/errors.hpp"
#include "common/format.hpp"

namespace dtwin {

class OptionCheck {
 public:
  explicit OptionCheck(std::string options) : options_(std::move(options)) {}
  /// "<options>.<field>": the where() of an InputError about `field`.
  std::string where(const std::string& field) const { return options_ + "." + field; }
  /// Throws InputError(where(field), rule) unless `ok`.
  void require(bool ok, const std::string& field, const std::string& rule) const {
    if (!ok) throw InputError(where(field), rule);
  }
  void finite(const std::string& field, double v) const {
    require(std::isfinite(v), field, "must be a finite number, got " + formatNumber(v));
  }
  /// v > 0 and finite.
  void positive(const std::string& field, double v) const {
    require(std::isfinite(v) && v > 0.0, field,
            "must be a finite number > 0, got " + formatNumber(v));
  }
  /// v >= 0 and finite.
  void nonNegative(const std::string& field, double v) const {
    require(std::isfinite(v) && v >= 0.0, field,
            "must be a finite number >= 0, got " + formatNumber(v));
  }
  /// v in (0, 1).
  void open01(const std::string& field, double v) const {
    require(v > 0.0 && v < 1.0, field, "must lie in (0, 1), got " + formatNumber(v));
  }
  /// v in [lo, hi] and finite.
  void inRange(const std::string& field, double v, double lo, double hi) const {
    require(
        std::isfinite(v) && v >= lo && v <= hi, field,
        "must lie in [" + formatNumber(lo) + ", " + formatNumber(hi) + "], got " + formatNumber(v));
  }
  void atLeast(const std::string& field, long long v, long long min) const {
    require(v >= min, field, "must be >= " + std::to_string(min) + ", got " + std::to_string(v));
  }
  void atMost(const std::string& field, long long v, long long max) const {
    require(v <= max, field, "must be <= " + std::to_string(max) + ", got " + std::to_string(v));
  }
  void nonEmpty(const std::string& field, const std::string& v) const {
    require(!v.empty(), field, "must not be empty");
  }
  const std::string& options() const { return options_; }

 private:
  std::string options_;
};

}  // namespace dtwin
