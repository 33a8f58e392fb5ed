// Fuzz harness: the vehicle data file reader (io/vehicle_file.hpp loadVehicleFile) into a fresh
// declaration of every vehicle parameter.
#include "io/vehicle_file.hpp"
#include "tests/fuzz/fuzz_common.hpp"
#include "twin/model.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace dtwin::fuzz;
  static const auto path = scratch() / "vehicle.toml";
  writeBytes(path, data, size);
  guarded([&] {
    dtwin::ParameterTable table = dtwin::declareVehicleParameters(dtwin::EffectCatalog{});
    dtwin::loadVehicleFile(table, path.string());
  });
  return 0;
}
