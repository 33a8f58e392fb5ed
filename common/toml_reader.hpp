#pragma once
// Reading one table of a TOML file (the study file) so that nothing is silently ignored: every
// key read is remembered and finish() reports the rest as unknown fields, with a "did you mean".
// Errors name the file, the line and the dotted field (InputError). Used by the study reader
// (io/study.cpp) and by each road type, which reads its own table (twin/roads/).
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/names.hpp"

namespace dtwin {

/// Reader over one TOML table that remembers which keys were consumed, so that unknown keys are
/// reported instead of silently ignored.
class TableReader {
 public:
  TableReader(const toml::table& t, std::string file, std::string prefix)
      : t_(t), file_(std::move(file)), prefix_(std::move(prefix)) {}

  std::string where(const std::string& key) const {
    const toml::node* n = t_.get(key);
    const int line =
        n ? static_cast<int>(n->source().begin.line) : static_cast<int>(t_.source().begin.line);
    return file_ + ":" + std::to_string(line) + ": " + field(key);
  }
  std::string field(const std::string& key) const {
    return prefix_.empty() ? key : prefix_ + "." + key;
  }
  bool has(const std::string& key) const { return t_.contains(key); }
  /// A path as the file gives it, resolved against the file's folder unless absolute.
  std::string resolvePath(const std::string& p) const {
    namespace fs = std::filesystem;
    return fs::path(p).is_absolute()
               ? p
               : (fs::path(file_).parent_path() / p).lexically_normal().string();
  }
  /// True when `key` holds a table (an inline { ... } or a [section]).
  bool isTable(const std::string& key) const {
    const toml::node* n = t_.get(key);
    return n && n->is_table();
  }

  std::optional<double> number(const std::string& key) {
    used_.insert(key);
    const toml::node* n = t_.get(key);
    if (!n) return std::nullopt;
    if (auto v = n->value<double>()) {
      if (!std::isfinite(*v))
        throw InputError(where(key), "must be a finite number, got " + formatNumber(*v));
      return *v;
    }
    throw InputError(where(key), "must be a number");
  }
  double number(const std::string& key, double def) { return number(key).value_or(def); }
  double required(const std::string& key) {
    auto v = number(key);
    if (!v) throw InputError(where(key), "is required");
    return *v;
  }
  double positive(const std::string& key, double def) {
    const double v = number(key, def);
    if (!(v > 0)) throw InputError(where(key), "must be > 0, got " + std::to_string(v));
    return v;
  }
  std::optional<std::string> string(const std::string& key) {
    used_.insert(key);
    const toml::node* n = t_.get(key);
    if (!n) return std::nullopt;
    if (auto v = n->value<std::string>()) return *v;
    throw InputError(where(key), "must be a string");
  }
  std::optional<bool> boolean(const std::string& key) {
    used_.insert(key);
    const toml::node* n = t_.get(key);
    if (!n) return std::nullopt;
    if (auto v = n->value_exact<bool>()) return *v;
    throw InputError(where(key), "must be true or false");
  }
  std::optional<long> integer(const std::string& key) {
    used_.insert(key);
    const toml::node* n = t_.get(key);
    if (!n) return std::nullopt;
    if (auto v = n->value_exact<int64_t>()) return static_cast<long>(*v);
    throw InputError(where(key), "must be an integer");
  }
  const toml::table* table(const std::string& key) {
    used_.insert(key);
    const toml::node* n = t_.get(key);
    if (!n) return nullptr;
    if (auto* tt = n->as_table()) return tt;
    throw InputError(where(key), "must be a table");
  }
  const toml::array* array(const std::string& key) {
    used_.insert(key);
    const toml::node* n = t_.get(key);
    if (!n) return nullptr;
    if (auto* a = n->as_array()) return a;
    throw InputError(where(key), "must be an array");
  }
  std::vector<std::string> strings(const std::string& key) {
    std::vector<std::string> out;
    if (auto* a = array(key))
      for (auto&& el : *a) {
        auto v = el.value<std::string>();
        if (!v) throw InputError(where(key), "must be an array of strings");
        out.push_back(*v);
      }
    return out;
  }
  /// Throws for any key not read.
  void finish() const {
    for (auto&& [k, n] : t_) {
      const std::string key(k.str());
      if (!used_.count(key)) {
        std::vector<std::string> known(used_.begin(), used_.end());
        const std::string hint = closestName(key, known);
        throw InputError(
            where(key),
            "unknown field" + (hint.empty() ? std::string() : " (did you mean '" + hint + "'?)"));
      }
    }
  }
  const std::string& file() const { return file_; }

 private:
  const toml::table& t_;
  std::string file_, prefix_;
  std::set<std::string> used_;
};

}  // namespace dtwin
