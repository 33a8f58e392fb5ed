// MF4 logs through the vendored mdflib (io/mdf_log.hpp): the file's blocks, a group's channels
// with their conversions applied, and the writer of the tests' and the bench's logs.
#include "io/mdf_log.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <streambuf>

#include <mdf/ichannel.h>
#include <mdf/ichannelconversion.h>
#include <mdf/ichannelgroup.h>
#include <mdf/ichannelobserver.h>
#include <mdf/idatagroup.h>
#include <mdf/mdffactory.h>
#include <mdf/mdffile.h>
#include <mdf/mdflogstream.h>
#include <mdf/mdfreader.h>
#include <mdf/mdfwriter.h>

#include "common/errors.hpp"
#include "io/mdf_structure.hpp"

namespace dtwin {

namespace {

/// The bytes of a log as a read-only stream (mdflib reads through a std::streambuf), no copy.
class MdfMemoryBuffer : public std::streambuf {
 public:
  explicit MdfMemoryBuffer(const std::string& bytes) {
    char* p = const_cast<char*>(bytes.data());  // never written: the get area only
    setg(p, p, p + bytes.size());
  }

 protected:
  pos_type seekoff(off_type off, std::ios_base::seekdir dir, std::ios_base::openmode) override {
    const off_type base = dir == std::ios_base::beg   ? 0
                          : dir == std::ios_base::cur ? gptr() - eback()
                                                      : egptr() - eback();
    const off_type to = base + off;
    if (to < 0 || to > egptr() - eback()) return pos_type(off_type(-1));
    setg(eback(), eback() + to, egptr());
    return pos_type(to);
  }
  pos_type seekpos(pos_type pos, std::ios_base::openmode which) override {
    return seekoff(off_type(pos), std::ios_base::beg, which);
  }
};

/// mdflib reports its errors to a log function: the last one of this thread is kept, to be named
/// in the error the import raises.
thread_local std::string mdf_last_error;

void installMdfLog() {
  static std::once_flag once;
  std::call_once(once, [] {
    mdf::MdfLogStream::SetLogFunction1(
        [](const MdfLocation&, mdf::MdfLogSeverity severity, const std::string& text) {
          if (severity >= mdf::MdfLogSeverity::kError) mdf_last_error = text;
        });
  });
}

std::string mdfReason(const std::string& fallback) {
  std::string s = mdf_last_error.empty() ? fallback : mdf_last_error;
  mdf_last_error.clear();
  std::replace(s.begin(), s.end(), '\n', ' ');
  std::replace(s.begin(), s.end(), '\r', ' ');
  return s;
}

std::string conversionName(const mdf::IChannelConversion* cc) {
  using mdf::ConversionType;
  if (cc == nullptr) return "identity";
  switch (cc->Type()) {
    case ConversionType::NoConversion:
      return "identity";
    case ConversionType::Linear:
      return "linear";
    case ConversionType::Rational:
      return "rational";
    case ConversionType::Algebraic:
      return "algebraic";
    case ConversionType::ValueToValueInterpolation:
      return "value-to-value with interpolation";
    case ConversionType::ValueToValue:
      return "value-to-value";
    case ConversionType::ValueRangeToValue:
      return "range-to-value";
    case ConversionType::ValueToText:
      return "value-to-text";
    case ConversionType::ValueRangeToText:
      return "range-to-text";
    case ConversionType::TextToValue:
      return "text-to-value";
    case ConversionType::TextToTranslation:
      return "text-to-text";
    case ConversionType::BitfieldToText:
      return "bitfield-to-text";
    default:
      return "unknown";
  }
}

/// A conversion whose result is a number the import can take.
bool numericConversion(const std::string& name) {
  return name == "identity" || name == "linear" || name == "rational" ||
         name == "value-to-value with interpolation" || name == "value-to-value" ||
         name == "range-to-value";
}

bool textData(const mdf::IChannel& cn) {
  using mdf::ChannelDataType;
  switch (cn.DataType()) {
    case ChannelDataType::UnsignedIntegerLe:
    case ChannelDataType::UnsignedIntegerBe:
    case ChannelDataType::SignedIntegerLe:
    case ChannelDataType::SignedIntegerBe:
    case ChannelDataType::FloatLe:
    case ChannelDataType::FloatBe:
      return false;
    default:
      return true;
  }
}

/// The channel's unit: its own, else its conversion's.
std::string channelUnit(const mdf::IChannel& cn) {
  if (cn.IsUnitValid()) return cn.Unit();
  const auto* cc = cn.ChannelConversion();
  return cc != nullptr && cc->IsUnitValid() ? cc->Unit() : std::string();
}

/// An opened log: the reader with its blocks read (not the data).
struct MdfOpened {
  std::shared_ptr<MdfMemoryBuffer> buffer;
  std::unique_ptr<mdf::MdfReader> reader;
  std::vector<std::pair<mdf::IDataGroup*, mdf::IChannelGroup*>>
      groups;  ///< every channel group, in file order
};

/// The log opened by mdflib after the structure check (its DZ blocks inflated too when `data`: the
/// data will be read).
MdfOpened openMdf(const std::string& bytes, const std::string& name, bool data) {
  installMdfLog();
  mdf_last_error.clear();
  if (bytes.size() < 64 || bytes.compare(0, 8, "MDF     ") != 0)
    throw InputError(
        name, bytes.compare(0, 8, "UnFinMF ") == 0 && bytes.size() >= 64
                  ? "is an MDF file the logger did not finalise (its identification reads "
                    "'UnFinMF'): finalise it with the logger's tool first"
                  : "is not an MDF file: it does not begin with an MDF identification block");
  checkMdfStructure(
      bytes, name,
      data);  // mdflib reads a link to the wrong block, or a damaged DZ block, without a word
  MdfOpened o;
  o.buffer = std::make_shared<MdfMemoryBuffer>(bytes);
  try {
    o.reader = std::make_unique<mdf::MdfReader>(std::shared_ptr<std::streambuf>(o.buffer));
    if (!o.reader->IsOk())
      throw InputError(
          name, "cannot be read as MDF: " + mdfReason("its identification block is damaged"));
    const auto* file = o.reader->GetFile();
    if (file == nullptr || file->MainVersion() < 4)
      throw InputError(name, "is MDF " + (file ? file->Version() : std::string("?")) +
                                 ": only MDF 4 (.mf4) logs are read");
    if (!o.reader->ReadEverythingButData())
      throw InputError(name, "is truncated or damaged: " + mdfReason("its blocks cannot be read"));
    mdf::DataGroupList dgs;
    file->DataGroups(dgs);
    for (auto* dg : dgs)
      if (dg != nullptr)
        for (auto* cg : dg->ChannelGroups())
          if (cg != nullptr) o.groups.emplace_back(dg, cg);
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(name, "is truncated or damaged: " + std::string(e.what()));
  }
  if (o.groups.empty()) throw InputError(name, "holds no channel group (no data)");
  return o;
}

}  // namespace

bool isMdfLog(const std::string& name, std::string_view bytes) {
  std::string ext = name.size() >= 4 ? name.substr(name.size() - 4) : std::string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".mf4" || ext == ".mdf" || bytes.substr(0, 8) == "MDF     ";
}

MdfDirectory readMdfDirectory(const std::string& bytes, const std::string& name) {
  const MdfOpened o = openMdf(bytes, name, /*data=*/false);
  MdfDirectory d;
  d.version = o.reader->GetFile()->Version();
  for (const auto& [dg, cg] : o.groups) {
    MdfDirectory::Group g;
    g.name = cg->Name();
    g.samples = cg->NofSamples();
    for (const auto* cn : cg->Channels()) {
      if (cn == nullptr) continue;
      MdfDirectory::Channel c;
      c.name = cn->Name();
      c.unit = channelUnit(*cn);
      c.conversion = conversionName(cn->ChannelConversion());
      c.master =
          cn->Type() == mdf::ChannelType::Master || cn->Type() == mdf::ChannelType::VirtualMaster;
      c.text = textData(*cn) || !numericConversion(c.conversion);
      g.channels.push_back(c);
    }
    d.groups.push_back(std::move(g));
  }
  return d;
}

MdfGroupData readMdfGroup(const std::string& bytes, const std::string& name, std::size_t group,
                          const std::vector<std::string>& channels) {
  MdfOpened o = openMdf(bytes, name, /*data=*/true);
  if (group >= o.groups.size())
    throw InputError(name, "has no channel group " + std::to_string(group + 1));
  auto* dg = o.groups[group].first;
  auto* cg = o.groups[group].second;
  MdfGroupData out;
  out.name = cg->Name();
  const std::string gname =
      out.name.empty() ? "channel group " + std::to_string(group + 1) : "group '" + out.name + "'";
  const mdf::IChannel* master = cg->GetMasterChannel();
  if (master == nullptr)
    throw InputError(name + ": " + gname,
                     "has no master channel (time): its samples have no times");
  out.master = master->Name();
  out.master_unit = channelUnit(*master);
  std::vector<const mdf::IChannel*> cns;
  for (const auto& c : channels) {
    const mdf::IChannel* found = nullptr;
    for (const auto* cn : cg->Channels())
      if (cn != nullptr && cn->Name() == c) found = cn;
    if (found == nullptr) throw InputError(name + ": " + gname, "has no channel '" + c + "'");
    const std::string conv = conversionName(found->ChannelConversion());
    if (textData(*found) || !numericConversion(conv))
      throw InputError(
          name + ": channel '" + c + "' (" + gname + ")",
          "its values are " +
              (textData(*found) ? std::string("not numbers") : "text (a " + conv + " conversion)") +
              ": a measurement, a speed, a road or a mask must be a number");
    cns.push_back(found);
    out.channels.push_back({c, channelUnit(*found), conv, {}});
  }
  try {
    std::vector<mdf::ChannelObserverPtr> obs;
    obs.push_back(mdf::CreateChannelObserver(*dg, *cg, *master));
    for (const auto* cn : cns) obs.push_back(mdf::CreateChannelObserver(*dg, *cg, *cn));
    for (const auto& ob : obs)
      if (!ob)
        throw InputError(name + ": " + gname,
                         "cannot be read: " + mdfReason("mdflib made no observer"));
    if (!o.reader->ReadData(*dg))
      throw InputError(name + ": " + gname,
                       "is truncated or damaged: " + mdfReason("its data cannot be read"));
    const std::uint64_t n = cg->NofSamples();
    for (const auto& ob : obs)
      if (ob->NofSamples() != n)
        throw InputError(name + ": " + gname,
                         "holds " + std::to_string(ob->NofSamples()) + " of the " +
                             std::to_string(n) +
                             " samples it declares: the file is truncated or damaged");
    out.time.resize(n);
    for (std::uint64_t i = 0; i < n; ++i) {
      double t = 0;
      if (!obs[0]->GetEngValue(i, t) || !std::isfinite(t))
        throw InputError(
            name + ": " + gname + ": master '" + out.master + "' at sample " + std::to_string(i),
            "has no valid time");
      out.time[i] = t;
    }
    for (std::size_t k = 0; k < cns.size(); ++k) {
      auto& v = out.channels[k].values;
      v.resize(n);
      for (std::uint64_t i = 0; i < n; ++i) {
        double x = 0;
        v[i] = obs[k + 1]->GetEngValue(i, x) ? x : std::numeric_limits<double>::quiet_NaN();
      }
    }
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(name + ": " + gname, "is truncated or damaged: " + std::string(e.what()));
  }
  return out;
}

void writeMdfLog(const std::string& path, const std::vector<MdfWriteGroup>& groups, bool compress) {
  installMdfLog();
  auto writer = mdf::MdfFactory::CreateMdfWriter(mdf::MdfWriterType::Mdf4Basic);
  if (!writer || !writer->Init(path))
    throw std::runtime_error("writeMdfLog: cannot create " + path + ": " +
                             mdfReason("mdflib failed"));
  writer->CompressData(compress);
  auto* dg = writer->CreateDataGroup();
  std::vector<mdf::IChannelGroup*> cgs;
  std::vector<std::vector<mdf::IChannel*>> cns;  // per group: the master, then its channels
  for (const auto& g : groups) {
    auto* cg = mdf::MdfWriter::CreateChannelGroup(dg);
    cg->Name(g.name);
    auto* m = mdf::MdfWriter::CreateChannel(cg);
    m->Name(g.master);
    m->Type(mdf::ChannelType::Master);
    m->Sync(mdf::ChannelSyncType::Time);
    m->DataType(mdf::ChannelDataType::FloatLe);
    m->DataBytes(8);
    m->Unit(g.master_unit);
    m->CalculateMasterTime(
        false);  // the times are written as given, not from the sample's timestamp
    cns.push_back({m});
    for (const auto& c : g.channels) {
      if (c.values.size() != g.time.size())
        throw std::runtime_error("writeMdfLog: channel " + c.name +
                                 " has another length than its master");
      auto* cn = mdf::MdfWriter::CreateChannel(cg);
      cn->Name(c.name);
      cn->Type(mdf::ChannelType::FixedLength);
      cn->DataType(mdf::ChannelDataType::FloatLe);
      cn->DataBytes(8);
      if (!c.unit.empty()) cn->Unit(c.unit);
      cns.back().push_back(cn);
      const auto& cv = c.conversion;
      if (cv.kind == "identity") continue;
      auto* cc = writer->CreateChannelConversion(cn);
      if (cv.kind == "linear") {
        cc->Type(mdf::ConversionType::Linear);
        cc->Parameter(0, cv.p[0]);
        cc->Parameter(1, cv.p[1]);
      } else if (cv.kind == "rational") {
        cc->Type(mdf::ConversionType::Rational);
        for (std::uint16_t i = 0; i < 6; ++i) cc->Parameter(i, cv.p[i]);
      } else if (cv.kind == "value_to_text") {
        cc->Type(mdf::ConversionType::ValueToText);
        if (cv.texts.size() >= 0xFFFF)
          throw std::runtime_error("writeMdfLog: too many conversion texts");
        for (std::size_t i = 0; i < cv.texts.size(); ++i) {
          cc->Parameter(static_cast<std::uint16_t>(i), cv.p[i]);
          cc->Reference(static_cast<std::uint16_t>(i), cv.texts[i]);
        }
        cc->Reference(static_cast<std::uint16_t>(cv.texts.size()), "unknown");
      } else {
        throw std::runtime_error("writeMdfLog: unknown conversion " + cv.kind);
      }
    }
    cgs.push_back(cg);
  }
  if (!writer->InitMeasurement())
    throw std::runtime_error("writeMdfLog: " + mdfReason("InitMeasurement failed"));
  const std::uint64_t start = 1'700'000'000'000'000'000ULL;
  writer->StartMeasurement(start);
  // The samples of all groups in time order, as a logger writes them.
  std::vector<std::size_t> next(groups.size(), 0);
  std::uint64_t last_ns = start;
  for (;;) {
    std::size_t pick = groups.size();
    for (std::size_t g = 0; g < groups.size(); ++g)
      if (next[g] < groups[g].time.size() &&
          (pick == groups.size() || groups[g].time[next[g]] < groups[pick].time[next[pick]]))
        pick = g;
    if (pick == groups.size()) break;
    const auto& g = groups[pick];
    const std::size_t i = next[pick]++;
    auto* cg = cgs[pick];
    cns[pick][0]->SetChannelValue(g.time[i]);
    for (std::size_t k = 0; k < g.channels.size(); ++k)
      cns[pick][k + 1]->SetChannelValue(g.channels[k].values[i]);  // NaN: a dropout
    const double rel = g.time[i] - groups[0].time.front();
    last_ns = start + static_cast<std::uint64_t>(std::max(0.0, rel) * 1e9);
    writer->SaveSample(*cg, last_ns);
  }
  writer->StopMeasurement(last_ns);
  if (!writer->FinalizeMeasurement())
    throw std::runtime_error("writeMdfLog: " + mdfReason("FinalizeMeasurement failed"));
}

}  // namespace dtwin
