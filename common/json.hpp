#pragma once
// Reading the project's own text and JSON files with errors that name the file, and numbers in
// JSON that may be non-finite (JSON has no inf or nan: they are written as the strings "inf",
// "-inf" and "nan").
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/files.hpp"  // readTextFile

namespace dtwin {

/// `path` parsed as JSON; InputError naming the file when it cannot be read (with `hint`) or is not
/// valid JSON.
nlohmann::json readJsonFile(const std::string& path, const std::string& hint = "");

/// A JSON library error in words: nlohmann's "[json.exception.parse_error.101] parse error at line
/// 1, column 1: syntax error ..." without its bracketed identifier ("parse error at line 1, ...").
std::string jsonErrorInWords(const std::exception& e);

/// `v` as a JSON number, or "inf" / "-inf" / "nan" when it is not finite.
nlohmann::json jsonNumber(double v);
/// The inverse of jsonNumber (any other string reads as NaN).
double numberFromJson(const nlohmann::json& j);
/// jsonNumber of every element, and its inverse.
nlohmann::json jsonNumbers(const std::vector<double>& v);
std::vector<double> numbersFromJson(const nlohmann::json& j);

}  // namespace dtwin
