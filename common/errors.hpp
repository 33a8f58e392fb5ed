#pragma once
// Error levels (see docs/architecture.md):
//  * InputError  - something a user supplied is wrong (file, field, option, number). Thrown; the
//                  CLI prints what() on one line and exits with code 2.
//  * DTWIN_CHECK - an always-on check of an impossible internal state; throws std::logic_error.
#include <stdexcept>
#include <string>

namespace dtwin {

class InputError : public std::runtime_error {
 public:
  /// `where` names the file and the field or line ("study.toml: scenarios.lab.road.height_m"),
  /// `rule` the rule that was broken ("must be > 0, got -0.2").
  InputError(std::string where, std::string rule)
      : std::runtime_error(where.empty() ? rule : where + ": " + rule),
        where_(std::move(where)), rule_(std::move(rule)) {}
  const std::string& where() const { return where_; }
  const std::string& rule() const { return rule_; }

 private:
  std::string where_;
  std::string rule_;
};

}  // namespace dtwin

#define DTWIN_CHECK(cond, msg)                                                          \
  do {                                                                                  \
    if (!(cond))                                                                        \
      throw std::logic_error(std::string("internal error: ") + (msg) + " [" #cond "] (" \
                             __FILE__ ":" + std::to_string(__LINE__) + ")");            \
  } while (0)
