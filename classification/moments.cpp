#include "classification/moments.hpp"
#include "common/format.hpp"

#include <unistd.h>

#include <Eigen/Core>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include "common/errors.hpp"
#include "common/files.hpp"

namespace dtwin::classify {

namespace {

constexpr const char* kMomentsWhere = "moment accumulator";
constexpr double kFormatVersion = 1.0;
constexpr std::size_t kHeader = 5;
constexpr char kFileTag[8] = {'D', 'T', 'W', 'M', 'O', 'M', '0', '1'};

std::size_t flatSize(std::size_t p, bool track) {
  return kHeader + p + p * (p + 1) / 2 + (track ? p + 1 : 0);
}

// A stored count or dimension must be a non-negative integer below 2^53.
bool isCount(double v) {
  return std::isfinite(v) && v >= 0 && v <= 9007199254740992.0 && v == std::floor(v);
}

}  // namespace

MomentAccumulator::MomentAccumulator(int dimension, const MomentOptions& options)
    : p_(dimension), track_(options.track_fourth_moment) {
  options.validate();
  if (dimension < 1)
    throw InputError(kMomentsWhere, "dimension must be >= 1, got " + std::to_string(dimension));
  mean_ = Eigen::VectorXd::Zero(p_);
  m2_ = Eigen::MatrixXd::Zero(p_, p_);
  if (track_) t_ = Eigen::VectorXd::Zero(p_);
}

void MomentAccumulator::checkVector(const Eigen::Ref<const Eigen::VectorXd>& x, const char* what,
                                    Eigen::Index column) const {
  const std::string name =
      column < 0 ? std::string(what) : std::string(what) + " column " + std::to_string(column);
  if (x.size() != p_)
    throw InputError(kMomentsWhere, name + " has length " + std::to_string(x.size()) +
                                        ", expected " + std::to_string(p_));
  if (!x.allFinite()) {
    Eigen::Index i = 0;
    while (std::isfinite(x[i])) ++i;
    throw InputError(kMomentsWhere, name + " entry " + std::to_string(i) + " is " +
                                        formatNumber(x[i], 17) + " (must be finite)");
  }
}

template <class M2Times, class AddScatter>
void MomentAccumulator::mergeSet(std::int64_t nb, const Eigen::VectorXd& mean_b, M2Times m2b_times,
                                 double trace_m2b, const Eigen::VectorXd* t_b, double q_b,
                                 AddScatter add_scatter_b, bool welford_mean) {
  if (nb == 0) return;
  if (n_ == 0) {  // C = B (m2_ is still all zero)
    mean_ = mean_b;
    add_scatter_b();
    if (track_) {
      t_ = *t_b;
      q_ = q_b;
    }
    n_ = nb;
    return;
  }
  const double na = static_cast<double>(n_);
  const double nbd = static_cast<double>(nb);
  const double n = na + nbd;
  const Eigen::VectorXd delta = mean_b - mean_;
  Eigen::VectorXd mean_c = welford_mean ? Eigen::VectorXd(mean_ + delta / n)
                                        : Eigen::VectorXd((na * mean_ + nbd * mean_b) / n);
  if (track_) {
    // Move both sides to the new centre μ_C (formulas in the header), using M2_A before update.
    const Eigen::VectorXd d_a = mean_c - mean_;
    const Eigen::VectorXd d_b = mean_c - mean_b;
    const double tr_a = m2_.diagonal().sum();
    const Eigen::VectorXd m2a_da = m2_.selfadjointView<Eigen::Upper>() * d_a;
    const Eigen::VectorXd m2b_db = m2b_times(d_b);
    const double sa = d_a.squaredNorm();
    const double sb = d_b.squaredNorm();
    const double q_a =
        q_ + 4.0 * d_a.dot(m2a_da) + na * sa * sa - 4.0 * t_.dot(d_a) + 2.0 * sa * tr_a;
    const double q_bc =
        q_b + 4.0 * d_b.dot(m2b_db) + nbd * sb * sb - 4.0 * t_b->dot(d_b) + 2.0 * sb * trace_m2b;
    const Eigen::VectorXd t_a = t_ - 2.0 * m2a_da - tr_a * d_a - (na * sa) * d_a;
    const Eigen::VectorXd t_bc = *t_b - 2.0 * m2b_db - trace_m2b * d_b - (nbd * sb) * d_b;
    q_ = q_a + q_bc;
    t_ = t_a + t_bc;
  }
  // M2_C = M2_A + M2_B + (n_A n_B / n) δ δᵀ (upper triangle).
  add_scatter_b();
  m2_.selfadjointView<Eigen::Upper>().rankUpdate(delta, na * nbd / n);
  mean_ = std::move(mean_c);
  n_ += nb;
}

void MomentAccumulator::add(const Eigen::VectorXd& x) {
  checkVector(x, "vector", -1);
  if (!track_) {
    // Welford: n ← n + 1, δ = x − μ, μ ← μ + δ / n, M2 ← M2 + ((n − 1) / n) δ δᵀ.
    ++n_;
    const double n = static_cast<double>(n_);
    const Eigen::VectorXd delta = x - mean_;
    mean_ += delta / n;
    if (n_ > 1) m2_.selfadjointView<Eigen::Upper>().rankUpdate(delta, (n - 1.0) / n);
    return;
  }
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(p_);
  // NOLINTBEGIN(performance-no-automatic-move): `zero` is captured, not the lambda's own: never moved
  mergeSet(
      1, x, [&](const Eigen::VectorXd&) { return zero; }, 0.0, &zero, 0.0, [] {}, true);
  // NOLINTEND(performance-no-automatic-move)
}

void MomentAccumulator::addBlock(const Eigen::MatrixXd& X) {
  if (X.rows() != p_)
    throw InputError(kMomentsWhere, "block has " + std::to_string(X.rows()) + " rows, expected " +
                                        std::to_string(p_));
  if (X.cols() < 1) throw InputError(kMomentsWhere, "block has no columns");
  for (Eigen::Index j = 0; j < X.cols(); ++j) checkVector(X.col(j), "block", j);
  const Eigen::Index k = X.cols();
  // B = the columns of X: μ_B = X 1 / k, C = X − μ_B 1ᵀ, M2_B = C Cᵀ.
  const Eigen::VectorXd mean_b = X.rowwise().sum() / static_cast<double>(k);
  const Eigen::MatrixXd c = X.colwise() - mean_b;
  Eigen::VectorXd t_b;
  double q_b = 0.0, trace_b = 0.0;
  if (track_) {
    const Eigen::RowVectorXd q = c.colwise().squaredNorm();  // q_j = ‖c_j‖²
    t_b = c * q.transpose();                                 // T_B = C q
    q_b = q.squaredNorm();                                   // Q_B = Σ q_j²
    trace_b = q.sum();                                       // tr(M2_B) = Σ q_j
  }
  mergeSet(
      k, mean_b, [&](const Eigen::VectorXd& d) { return Eigen::VectorXd(c * (c.transpose() * d)); },
      trace_b, &t_b, q_b, [&] { m2_.selfadjointView<Eigen::Upper>().rankUpdate(c, 1.0); }, false);
}

void MomentAccumulator::merge(const MomentAccumulator& other) {
  if (other.p_ != p_)
    throw InputError(kMomentsWhere, "cannot merge an accumulator of dimension " +
                                        std::to_string(other.p_) + " into one of dimension " +
                                        std::to_string(p_));
  if (other.track_ != track_)
    throw InputError(kMomentsWhere, std::string("cannot merge accumulators with different "
                                                "track_fourth_moment (") +
                                        (track_ ? "true" : "false") + " vs " +
                                        (other.track_ ? "true" : "false") + ")");
  if (&other == this) {  // merging with itself: work on a copy
    // NOLINTNEXTLINE(performance-unnecessary-copy-initialization): merge() changes other (*this)
    const MomentAccumulator copy = other;
    merge(copy);
    return;
  }
  mergeSet(
      other.n_, other.mean_,
      [&](const Eigen::VectorXd& d) {
        return Eigen::VectorXd(other.m2_.selfadjointView<Eigen::Upper>() * d);
      },
      other.m2_.diagonal().sum(), &other.t_, other.q_,
      [&] { m2_.triangularView<Eigen::Upper>() += other.m2_; }, false);
}

Eigen::MatrixXd MomentAccumulator::covariance() const {
  if (n_ < 2)
    throw InputError(kMomentsWhere,
                     "covariance needs at least 2 vectors, got " + std::to_string(n_));
  Eigen::MatrixXd s = m2_.selfadjointView<Eigen::Upper>();
  s /= static_cast<double>(n_ - 1);
  return s;
}

const Eigen::VectorXd& MomentAccumulator::getThirdMoment() const {
  if (!track_)
    throw InputError(kMomentsWhere,
                     "third moment not tracked (set MomentOptions::track_fourth_moment)");
  return t_;
}

double MomentAccumulator::getFourthMoment() const {
  if (!track_)
    throw InputError(kMomentsWhere,
                     "fourth moment not tracked (set MomentOptions::track_fourth_moment)");
  return q_;
}

std::vector<double> MomentAccumulator::toVector() const {
  const std::size_t p = static_cast<std::size_t>(p_);
  std::vector<double> v;
  v.reserve(flatSize(p, track_));
  v.push_back(kFlatMagic);
  v.push_back(kFormatVersion);
  v.push_back(static_cast<double>(p_));
  v.push_back(static_cast<double>(n_));
  v.push_back(track_ ? 1.0 : 0.0);
  v.insert(v.end(), mean_.data(), mean_.data() + p);
  for (Eigen::Index j = 0; j < p_; ++j) {
    const double* col = m2_.col(j).data();
    v.insert(v.end(), col, col + j + 1);
  }
  if (track_) {
    v.insert(v.end(), t_.data(), t_.data() + p);
    v.push_back(q_);
  }
  return v;
}

MomentAccumulator MomentAccumulator::fromVector(const std::vector<double>& v) {
  const std::string where = "moment accumulator data";
  if (v.size() < kHeader)
    throw InputError(where, "has " + std::to_string(v.size()) + " values, fewer than the " +
                                std::to_string(kHeader) + "-value header");
  if (v[0] != kFlatMagic)
    throw InputError(where, "header[0] (magic) is " + formatNumber(v[0], 17) + ", expected " +
                                formatNumber(kFlatMagic, 17));
  if (v[1] != kFormatVersion)
    throw InputError(where,
                     "header[1] (format version) is " + formatNumber(v[1], 17) + ", expected 1");
  if (!isCount(v[2]) || v[2] < 1 || v[2] > 1e6)
    throw InputError(where, "header[2] (dimension) is " + formatNumber(v[2], 17) +
                                ", expected an integer in [1, 1e6]");
  if (!isCount(v[3]))
    throw InputError(where, "header[3] (count) is " + formatNumber(v[3], 17) +
                                ", expected a non-negative integer");
  if (v[4] != 0.0 && v[4] != 1.0)
    throw InputError(where,
                     "header[4] (track flag) is " + formatNumber(v[4], 17) + ", expected 0 or 1");
  const std::size_t p = static_cast<std::size_t>(v[2]);
  const bool track = v[4] == 1.0;
  if (v.size() != flatSize(p, track))
    throw InputError(where, "has " + std::to_string(v.size()) + " values, expected " +
                                std::to_string(flatSize(p, track)) + " for dimension " +
                                std::to_string(p));
  for (std::size_t i = kHeader; i < v.size(); ++i)
    if (!std::isfinite(v[i]))
      throw InputError(where, "value " + std::to_string(i) + " is " + formatNumber(v[i], 17) +
                                  " (must be finite)");
  MomentOptions options;
  options.track_fourth_moment = track;
  MomentAccumulator acc(static_cast<int>(p), options);
  acc.n_ = static_cast<std::int64_t>(v[3]);
  std::size_t at = kHeader;
  std::memcpy(acc.mean_.data(), v.data() + at, p * sizeof(double));
  at += p;
  for (std::size_t j = 0; j < p; ++j) {
    std::memcpy(acc.m2_.col(static_cast<Eigen::Index>(j)).data(), v.data() + at,
                (j + 1) * sizeof(double));
    at += j + 1;
  }
  if (track) {
    std::memcpy(acc.t_.data(), v.data() + at, p * sizeof(double));
    at += p;
    acc.q_ = v[at++];
  }
  DTWIN_CHECK(at == v.size(), "flat layout size");
  return acc;
}

std::vector<std::uint8_t> MomentAccumulator::toBytes() const {
  const std::vector<double> v = toVector();
  std::vector<std::uint8_t> bytes(v.size() * sizeof(double));
  std::memcpy(bytes.data(), v.data(), bytes.size());
  return bytes;
}

MomentAccumulator MomentAccumulator::fromBytes(const std::vector<std::uint8_t>& bytes) {
  if (bytes.size() % sizeof(double) != 0)
    throw InputError("moment accumulator data",
                     "has " + std::to_string(bytes.size()) + " bytes, not a multiple of 8");
  std::vector<double> v(bytes.size() / sizeof(double));
  std::memcpy(v.data(), bytes.data(), bytes.size());
  return fromVector(v);
}

void MomentAccumulator::save(const std::string& path) const {
  const std::vector<double> v = toVector();
  std::string bytes(kFileTag, sizeof kFileTag);
  bytes.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(double));
  writeFileAtomic(path, bytes);
}

MomentAccumulator MomentAccumulator::load(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot open moment accumulator file");
  char tag[sizeof kFileTag];
  if (!in.read(tag, sizeof tag) || std::memcmp(tag, kFileTag, sizeof tag) != 0)
    throw InputError(path, "not a moment accumulator file (missing tag DTWMOM01)");
  in.seekg(0, std::ios::end);
  const std::streamoff end = in.tellg();
  in.seekg(sizeof tag, std::ios::beg);
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(end) - sizeof tag);
  if (!in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size())))
    throw InputError(path, "cannot read moment accumulator file");
  try {
    return fromBytes(bytes);
  } catch (const InputError& e) {
    throw InputError(path, e.rule());
  }
}

}  // namespace dtwin::classify
