#include "common/distributed.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <chrono>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <thread>

#include "common/errors.hpp"
#include "common/run_error.hpp"

#ifdef DTWIN_HAVE_MPI
#include <mpi.h>
#endif

namespace dtwin {

std::string rootFileBytes(const Distributed* processes, const std::string& path) {
  return onRoot(processes, [&] {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path, "cannot be read");
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  });
}
namespace {

#ifdef DTWIN_HAVE_MPI
void bcastBytes(std::string& s, int root, MPI_Comm comm) {
  unsigned long long len = s.size();
  MPI_Bcast(&len, 1, MPI_UNSIGNED_LONG_LONG, root, comm);
  s.resize(static_cast<std::size_t>(len));
  const std::size_t chunk = std::size_t(1) << 30;
  for (std::size_t off = 0; off < s.size(); off += chunk) {
    const int k = static_cast<int>(std::min(chunk, s.size() - off));
    MPI_Bcast(&s[off], k, MPI_CHAR, root, comm);
  }
}

bool mpiRunning() {
  int init = 0, fin = 0;
  MPI_Initialized(&init);
  MPI_Finalized(&fin);
  return init && !fin;
}

bool launchedByMpi() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(v)) return true;
  return false;
}

[[noreturn]] void terminateHandler() {
  // An exception nobody caught (or std::terminate for another reason) on one rank: take the
  // whole job down instead of leaving the other ranks waiting in a collective.
  if (mpiRunning()) MPI_Abort(MPI_COMM_WORLD, 1);
  std::abort();
}
#endif

void addField(std::string& out, const std::string& s) { out += std::to_string(s.size()) + ":" + s; }
std::string nextField(const std::string& in, std::size_t& pos) {
  const std::size_t colon = in.find(':', pos);
  DTWIN_CHECK(colon != std::string::npos, "malformed encoded exception");
  const std::size_t len = std::stoull(in.substr(pos, colon - pos));
  DTWIN_CHECK(colon + 1 + len <= in.size(), "malformed encoded exception");
  std::string s = in.substr(colon + 1, len);
  pos = colon + 1 + len;
  return s;
}

}  // namespace

struct Distributed::Comms {
#ifdef DTWIN_HAVE_MPI
  MPI_Comm work = MPI_COMM_NULL;  // the collectives of the program
  MPI_Comm exit = MPI_COMM_NULL;  // the exit agreement only (never mixed with unfinished work)
#endif
};

Distributed::Distributed() : comms_(std::make_unique<Comms>()) {}
Distributed::~Distributed() = default;

bool Distributed::builtWithMpi() {
#ifdef DTWIN_HAVE_MPI
  return true;
#else
  return false;
#endif
}

void Distributed::init(int* argc, char*** argv) {
#ifdef DTWIN_HAVE_MPI
  if (mpi_) return;
  const char* off = std::getenv("DTWIN_NO_MPI");
  if (off && *off && std::string(off) != "0") return;
  if (!launchedByMpi()) return;
  int provided = 0;
  if (MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
    std::fprintf(stderr, "twin: error: MPI_Init_thread failed\n");
    std::exit(1);
  }
  if (provided < MPI_THREAD_FUNNELED) {
    std::fprintf(stderr, "twin: error: the MPI library does not provide MPI_THREAD_FUNNELED\n");
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  mpi_ = true;
  std::set_terminate(terminateHandler);
  MPI_Comm_dup(MPI_COMM_WORLD, &comms_->work);
  MPI_Comm_dup(MPI_COMM_WORLD, &comms_->exit);
  MPI_Comm_rank(comms_->work, &rank_);
  MPI_Comm_size(comms_->work, &size_);
  MPI_Comm shm;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &shm);
  MPI_Comm_size(shm, &local_size_);
  MPI_Comm_free(&shm);
  if (rank_ != 0) {  // only the root prints
    std::fflush(stdout);
    std::fflush(stderr);
    saved_stderr_ = ::dup(STDERR_FILENO);
    const int null = ::open("/dev/null", O_WRONLY);
    if (null >= 0) {
      ::dup2(null, STDOUT_FILENO);
      ::dup2(null, STDERR_FILENO);
      ::close(null);
    }
  }
#else
  (void)argc;
  (void)argv;
#endif
}

int Distributed::finish(int rc, const std::string& message) {
#ifdef DTWIN_HAVE_MPI
  if (!mpi_) return rc;
  std::fflush(stdout);
  std::fflush(stderr);
  auto say = [&](const std::string& text) {
    const std::string line =
        "twin: rank " + std::to_string(rank_) + " of " + std::to_string(size_) + ": " + text + "\n";
    const int fd = saved_stderr_ >= 0 ? saved_stderr_ : STDERR_FILENO;
    if (::write(fd, line.data(), line.size()) < 0) {
    }
  };
  MPI_Request req;
  MPI_Ibarrier(comms_->exit, &req);
  const auto t0 = std::chrono::steady_clock::now();
  int arrived = 0;
  while (true) {
    MPI_Test(&req, &arrived, MPI_STATUS_IGNORE);
    if (arrived) break;
    if (rc != 0 && std::chrono::steady_clock::now() - t0 > std::chrono::seconds(120)) {
      say((message.empty() ? std::string("failed") : message) +
          " (the other ranks did not stop: aborting the job)");
      MPI_Abort(MPI_COMM_WORLD, rc);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  std::vector<int> rcs(static_cast<std::size_t>(size_));
  MPI_Allgather(&rc, 1, MPI_INT, rcs.data(), 1, MPI_INT, comms_->exit);
  int job = rcs[0];
  for (int r : rcs)
    if (job == 0 && r != 0) job = r;
  if (rank_ != 0 && rc != 0 && rcs[0] != rc) say(message.empty() ? std::string("failed") : message);
  if (rank_ == 0 && rc == 0 && job != 0)
    std::fprintf(stderr, "twin: error: another rank failed (exit code %d)\n", job);
  std::fflush(stderr);
  MPI_Comm_free(&comms_->work);
  MPI_Comm_free(&comms_->exit);
  MPI_Finalize();
  mpi_ = false;
  return job;
#else
  (void)message;
  return rc;
#endif
}

int Distributed::threadsPerRank(int requested) const {
  if (requested > 0 || size_ == 1) return requested;
  const int hw = static_cast<int>(std::thread::hardware_concurrency());
  return std::max(1, hw / std::max(1, local_size_));
}

void Distributed::barrier() const {
#ifdef DTWIN_HAVE_MPI
  if (mpi_ && size_ > 1) MPI_Barrier(comms_->work);
#endif
}

std::string Distributed::broadcastFromRoot(const std::string& payload,
                                           const std::exception_ptr& error) const {
#ifdef DTWIN_HAVE_MPI
  if (mpi_ && size_ > 1) {
    std::string msg;
    if (rank_ == 0) msg = error ? "E" + encodeException(error) : "V" + payload;
    bcastBytes(msg, 0, comms_->work);
    if (rank_ == 0) {
      if (error) std::rethrow_exception(error);
      return payload;
    }
    DTWIN_CHECK(!msg.empty(), "empty broadcast");
    if (msg[0] == 'E') throwEncoded(msg.substr(1));
    return msg.substr(1);
  }
#endif
  if (error) std::rethrow_exception(error);
  return payload;
}

void Distributed::gatherMap(std::vector<std::vector<double>>& out, long long local_fail,
                            const std::exception_ptr& error) const {
  if (error && local_fail < 0) local_fail = rank_;  // defensive: an error not tied to a task
#ifdef DTWIN_HAVE_MPI
  if (mpi_ && size_ > 1) {
    const std::size_t n = out.size(), size = static_cast<std::size_t>(size_);
    std::vector<double> buf;
    if (!error)
      for (std::size_t i = static_cast<std::size_t>(rank_); i < n; i += size) {
        buf.push_back(static_cast<double>(out[i].size()));
        buf.insert(buf.end(), out[i].begin(), out[i].end());
      }
    long long mine[2] = {static_cast<long long>(buf.size()), error ? local_fail : -1};
    std::vector<long long> all(2 * size);
    MPI_Allgather(mine, 2, MPI_LONG_LONG, all.data(), 2, MPI_LONG_LONG, comms_->work);
    long long fail = -1;
    for (std::size_t r = 0; r < size; ++r)
      if (all[2 * r + 1] >= 0 && (fail < 0 || all[2 * r + 1] < fail)) fail = all[2 * r + 1];
    if (fail >= 0) {
      const int owner = static_cast<int>(fail % static_cast<long long>(size_));
      std::string bytes = rank_ == owner ? encodeException(error) : std::string();
      bcastBytes(bytes, owner, comms_->work);
      if (rank_ == owner) std::rethrow_exception(error);
      throwEncoded(bytes);
    }
    std::vector<int> counts(size), displs(size);
    long long total = 0;
    for (std::size_t r = 0; r < size; ++r) {
      DTWIN_CHECK(all[2 * r] <= INT_MAX,
                  "a rank's results exceed 2^31 doubles: use smaller batches");
      counts[r] = static_cast<int>(all[2 * r]);
      displs[r] = static_cast<int>(total);
      total += all[2 * r];
      DTWIN_CHECK(total <= INT_MAX,
                  "the gathered results exceed 2^31 doubles: use smaller batches");
    }
    std::vector<double> recv(static_cast<std::size_t>(total));
    MPI_Allgatherv(buf.data(), counts[static_cast<std::size_t>(rank_)], MPI_DOUBLE, recv.data(),
                   counts.data(), displs.data(), MPI_DOUBLE, comms_->work);
    for (std::size_t r = 0; r < size; ++r) {
      std::size_t pos = static_cast<std::size_t>(displs[r]);
      const std::size_t end = pos + static_cast<std::size_t>(counts[r]);
      for (std::size_t i = r; i < n; i += size) {
        DTWIN_CHECK(pos < end, "gathered results are shorter than expected");
        const std::size_t len = static_cast<std::size_t>(recv[pos++]);
        DTWIN_CHECK(pos + len <= end, "gathered results are shorter than expected");
        if (r != static_cast<std::size_t>(rank_))
          out[i].assign(recv.begin() + static_cast<long>(pos),
                        recv.begin() + static_cast<long>(pos + len));
        pos += len;
      }
      DTWIN_CHECK(pos == end, "gathered results are longer than expected");
    }
    return;
  }
#endif
  if (error) std::rethrow_exception(error);
}

namespace {
constexpr long long kPiece = 1LL << 27;  // doubles per message (1 GiB): MPI counts are int
}  // namespace

void Distributed::sendDoubles(int to, const std::vector<double>& values) const {
#ifdef DTWIN_HAVE_MPI
  if (mpi_ && size_ > 1) {
    DTWIN_CHECK(to >= 0 && to < size_ && to != rank_, "sendDoubles: no such partner rank");
    long long n = static_cast<long long>(values.size());
    MPI_Send(&n, 1, MPI_LONG_LONG, to, 1, comms_->work);
    for (long long at = 0; at < n; at += kPiece)
      MPI_Send(values.data() + at, static_cast<int>(std::min(kPiece, n - at)), MPI_DOUBLE, to, 2,
               comms_->work);
    return;
  }
#endif
  (void)to;
  (void)values;
  DTWIN_CHECK(false, "sendDoubles needs more than one rank");
}

std::vector<double> Distributed::receiveDoubles(int from) const {
#ifdef DTWIN_HAVE_MPI
  if (mpi_ && size_ > 1) {
    DTWIN_CHECK(from >= 0 && from < size_ && from != rank_, "receiveDoubles: no such partner rank");
    long long n = 0;
    MPI_Recv(&n, 1, MPI_LONG_LONG, from, 1, comms_->work, MPI_STATUS_IGNORE);
    DTWIN_CHECK(n >= 0, "receiveDoubles: a negative length");
    std::vector<double> values(static_cast<std::size_t>(n));
    for (long long at = 0; at < n; at += kPiece)
      MPI_Recv(values.data() + at, static_cast<int>(std::min(kPiece, n - at)), MPI_DOUBLE, from, 2,
               comms_->work, MPI_STATUS_IGNORE);
    return values;
  }
#endif
  (void)from;
  DTWIN_CHECK(false, "receiveDoubles needs more than one rank");
  return {};
}

std::string encodeException(const std::exception_ptr& e) {
  std::string out;
  try {
    std::rethrow_exception(e);
  } catch (const InputError& x) {
    addField(out, "input");
    addField(out, x.where());
    addField(out, x.rule());
  } catch (const RunFailedError& x) {
    addField(out, "run");
    addField(out, x.what());
    addField(out, std::to_string(x.run()));
    addField(out, std::to_string(x.seed()));
  } catch (const std::logic_error& x) {
    addField(out, "logic");
    addField(out, x.what());
  } catch (const std::exception& x) {
    addField(out, "runtime");
    addField(out, x.what());
  } catch (...) {
    addField(out, "runtime");
    addField(out, "unknown exception");
  }
  return out;
}

void throwEncoded(const std::string& bytes) {
  std::size_t pos = 0;
  const std::string kind = nextField(bytes, pos);
  if (kind == "input") {
    std::string where = nextField(bytes, pos);
    std::string rule = nextField(bytes, pos);
    throw InputError(std::move(where), std::move(rule));
  }
  if (kind == "run") {
    const std::string what = nextField(bytes, pos);
    const std::size_t run = std::stoull(nextField(bytes, pos));
    const std::uint64_t seed = std::stoull(nextField(bytes, pos));
    throw RunFailedError(what, run, seed);
  }
  const std::string what = nextField(bytes, pos);
  if (kind == "logic") throw std::logic_error(what);
  throw std::runtime_error(what);
}

}  // namespace dtwin
