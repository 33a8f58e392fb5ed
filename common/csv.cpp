#include "common/csv.hpp"

#include <charconv>

#include "common/errors.hpp"

namespace dtwin {

namespace {
std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}
}  // namespace

CsvReader::CsvReader(const std::string& text, std::string name, char sep)
    : text_(text), name_(std::move(name)), sep_(sep) {
  if (text_.substr(0, 3) == "\xEF\xBB\xBF") pos_ = 3;
}

std::string CsvReader::where() const { return name_ + ":" + std::to_string(line_); }

bool CsvReader::next() {
  while (pos_ < text_.size()) {
    const std::size_t end = text_.find('\n', pos_);
    std::string_view line =
        text_.substr(pos_, end == std::string_view::npos ? std::string_view::npos : end - pos_);
    pos_ = end == std::string_view::npos ? text_.size() : end + 1;
    ++line_;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (trim(line).empty()) continue;
    fields_.clear();
    unquoted_.clear();
    std::size_t i = 0;
    while (true) {
      // One field: up to the next separator outside quotes.
      std::size_t j = i;
      while (j < line.size() && (line[j] == ' ' || line[j] == '\t')) ++j;
      if (j < line.size() && line[j] == '"') {
        std::string value;
        bool escaped = false;
        std::size_t k = j + 1;
        for (;; ++k) {
          if (k >= line.size()) throw InputError(where(), "a double quote is not closed");
          if (line[k] == '"') {
            if (k + 1 < line.size() && line[k + 1] == '"') {
              value += '"';
              escaped = true;
              ++k;
              continue;
            }
            break;
          }
          value += line[k];
        }
        std::size_t after = k + 1;
        while (after < line.size() && (line[after] == ' ' || line[after] == '\t')) ++after;
        // The next character must be the separator; with whitespace, some space must come first.
        if (after < line.size() && (sep_ == ' ' ? after == k + 1 : line[after] != sep_))
          throw InputError(where(), "text after a closing double quote");
        if (escaped) {
          unquoted_.push_back(std::move(value));
          fields_.push_back(unquoted_.back());  // a deque: earlier fields stay where they are
        } else {
          fields_.push_back(line.substr(j + 1, k - j - 1));
        }
        if (after >= line.size()) break;
        i = sep_ == ' ' ? after : after + 1;
      } else if (sep_ == ' ') {
        // Whitespace: a run of spaces and tabs is one separator (a column-aligned log).
        std::size_t s = j;
        while (s < line.size() && line[s] != ' ' && line[s] != '\t') ++s;
        fields_.push_back(line.substr(j, s - j));
        while (s < line.size() && (line[s] == ' ' || line[s] == '\t')) ++s;
        if (s >= line.size()) break;
        i = s;
      } else {
        const std::size_t s = line.find(sep_, i);
        fields_.push_back(
            trim(line.substr(i, s == std::string_view::npos ? std::string_view::npos : s - i)));
        if (s == std::string_view::npos) break;
        i = s + 1;
      }
    }
    return true;
  }
  return false;
}

}  // namespace dtwin
