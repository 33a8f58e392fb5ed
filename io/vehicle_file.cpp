// The vehicle data file reader (io/vehicle_file.hpp).
#include "io/vehicle_file.hpp"

#include <filesystem>
#include <functional>

#include <toml++/toml.h>

#include "common/errors.hpp"
#include "common/files.hpp"
#include "twin/model.hpp"

namespace dtwin {
namespace {

std::string vehicleFileLine(const std::string& path, const toml::node& n) {
  const auto& src = n.source();
  return path + ":" + std::to_string(src.begin.line);
}

}  // namespace

void loadVehicleFile(ParameterTable& table, const std::string& path) {
  namespace fs = std::filesystem;
  if (!fs::exists(path)) throw InputError(path, "vehicle file not found");
  if (fs::is_directory(path)) throw InputError(path, "is a folder, not a vehicle file");
  toml::table root;
  try {
    root = toml::parse(readTextFile(path), path);
  } catch (const toml::parse_error& e) {
    throw InputError(path + ":" + std::to_string(e.source().begin.line),
                     std::string("malformed TOML: ") + std::string(e.description()));
  }
  std::function<void(const toml::table&, const std::string&)> walk =
      [&](const toml::table& tbl, const std::string& prefix) {
        for (auto&& [k, node] : tbl) {
          const std::string name =
              prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
          const std::string where = vehicleFileLine(path, node) + ": " + name;
          if (name == "vehicle") {  // descriptive header table
            continue;
          }
          const auto* sub = node.as_table();
          if (!sub)
            throw InputError(
                where,
                "each parameter must be a table { value = .., unit = \"..\", source = \"..\" }");
          if (!sub->contains("value")) {
            walk(*sub, name);
            continue;
          }
          const auto v = (*sub)["value"].value<double>();
          const auto u = (*sub)["unit"].value<std::string>();
          const auto src = (*sub)["source"].value<std::string>();
          if (!v) throw InputError(where + ".value", "must be a number");
          if (!u) throw InputError(where + ".unit", "is required (a string such as \"kg\")");
          if (!src)
            throw InputError(where + ".source", "is required: say where the number comes from");
          for (auto&& [kk, _] : *sub)
            if (kk != "value" && kk != "unit" && kk != "source")
              throw InputError(where + "." + std::string(kk.str()),
                               "unknown key (allowed: value, unit, source)");
          table.set(name, *v, path + " (" + *src + ")", where, *u);
        }
      };
  walk(root, "");
  checkChassisInertias(table, path);
}

}  // namespace dtwin
