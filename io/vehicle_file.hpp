#pragma once
// The vehicle data file (data/vehicle/*.toml): every fixed value of the vehicle with its unit and
// where the number comes from (docs/data-files.md).
#include <string>

#include "twin/parameters.hpp"

namespace dtwin {

/// Reads a vehicle data file (TOML; each leaf `name = { value = .., unit = "..", source = ".." }`)
/// into `table`. Errors name the file, the line and the field.
void loadVehicleFile(ParameterTable& table, const std::string& path);

}  // namespace dtwin
