#include "twin/road_setting.hpp"

#include "common/errors.hpp"
#include "common/names.hpp"
#include "common/toml_reader.hpp"
#include "twin/roads/bump.hpp"
#include "twin/roads/crg.hpp"
#include "twin/roads/csv.hpp"
#include "twin/roads/csv_time.hpp"
#include "twin/roads/flat.hpp"
#include "twin/roads/iso8608.hpp"

namespace dtwin {

const Registry<RoadParser>& roadTypes() {
  // The registry: one line per road type.
  static const Registry<RoadParser> r(
      "road type",
      {
          {"flat", "a flat road", &FlatRoadSetting::parse},
          {"bump", "a one-cosine bump across both tracks, reached at time_s",
           &BumpRoadSetting::parse},
          {"iso8608", "an ISO 8608 random road of a class A..H, smooth until smooth_until_s",
           &IsoRoadSetting::parse},
          {"csv", "a measured profile: distance_m,left_m,right_m", &CsvRoadSetting::parse},
          {"csv_time",
           "a road logged against time (height or road velocity), mapped to distance through the "
           "speed",
           &CsvTimeRoadSetting::parse},
          {"crg", "an ASAM OpenCRG road surface: two wheel tracks at offsets v along u",
           &CrgRoadSetting::parse},
      });
  return r;
}

std::vector<std::string> roadTypeNames() { return roadTypes().names(); }

std::shared_ptr<const RoadSetting> parseRoadSetting(TableReader& r) {
  const toml::table* t = r.table("road");
  if (!t) throw InputError(r.where("road"), "is required (a table with a 'type')");
  TableReader rr(*t, r.file(), r.field("road"));
  const std::string type = rr.string("type").value_or("");
  if (type.empty())
    throw InputError(rr.where("type"),
                     unknownNameRule(roadTypes().what(), type, roadTypes().names()));
  auto setting = roadTypes().at(type, rr.where("type")).value(rr);
  rr.finish();
  return setting;
}

std::shared_ptr<const RoadSetting> flatRoadSetting() {
  static const auto flat = std::make_shared<const FlatRoadSetting>();
  return flat;
}

}  // namespace dtwin
