#pragma once
// Reading CSV text as users' files come: a UTF-8 byte-order mark, CR line ends, blank lines,
// spaces around fields and double quotes around a field (with "" for a quote inside) are all
// accepted. Fields are views into the text: no copies, so a million-row log reads in well under
// a second. Errors are the caller's: where() names file:line for them.
#include <deque>
#include <string>
#include <string_view>
#include <vector>

#include "common/format.hpp"  // parseNumber, for the fields

namespace dtwin {

class CsvReader {
 public:
  /// `text` must outlive the reader; `name` (the file) prefixes where(); `sep` the field separator.
  /// `sep` = ' ' means whitespace: a run of spaces and tabs is one separator (a column-aligned
  /// log; an empty cell cannot be written there, a missing value is NaN).
  CsvReader(const std::string& text, std::string name, char sep = ',');
  /// Advances to the next non-blank line and splits it; false at the end of the text. Throws
  /// InputError(where(), ...) for a quote left open.
  bool next();
  /// The current line's fields, trimmed and unquoted.
  const std::vector<std::string_view>& fields() const { return fields_; }
  /// 1-based line number of the current line.
  long line() const { return line_; }
  /// "name:line".
  std::string where() const;
  /// Bytes read so far and in all (for a progress bar).
  std::size_t offset() const { return pos_; }
  std::size_t size() const { return text_.size(); }

 private:
  std::string_view text_;
  std::string name_;
  char sep_;
  std::size_t pos_ = 0;
  long line_ = 0;
  std::vector<std::string_view> fields_;
  std::deque<std::string>
      unquoted_;  // fields that held "" (rare): their unescaped text (stable addresses)
};

}  // namespace dtwin
