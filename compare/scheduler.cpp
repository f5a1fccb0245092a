#include "scheduler.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <ctime>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <exception>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>

#include "dsmc/progress_counter.hpp"
#include "dsmc/unit_cost.hpp"
#include "model/errors.hpp"

#ifdef GRANMIX_MPI
#include <mpi.h>
#endif

namespace granmix::compare::scheduler {

namespace {

// Environment variables that MPI launchers set in every process they start.
bool started_by_launcher() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMI_RANK", "PMIX_RANK"})
    if (std::getenv(v)) return true;
  return false;
}

struct World {
  int rank = 0, size = 1;
  bool mpi = false;
};

#ifdef GRANMIX_MPI
// MPI reports errors through return codes (MPI_ERRORS_RETURN is set), each checked here.
void check(int rc, const char* call) {
  if (rc == MPI_SUCCESS) return;
  char text[MPI_MAX_ERROR_STRING];
  int n = 0;
  MPI_Error_string(rc, text, &n);
  throw std::runtime_error(std::string("MPI: ") + call + " failed: " + std::string(text, static_cast<std::size_t>(n)));
}
#endif

// The world once world() has been called (finish() and abort() must not start MPI to stop it).
World* started = nullptr;

World& world() {
  static World w = [] {
    World w;
    if (!started_by_launcher()) return w;
#ifdef GRANMIX_MPI
    int provided = 0;
    check(MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
    w.mpi = true;
    check(MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN), "MPI_Comm_set_errhandler");
    // Worker threads compute while the main thread alone talks MPI: FUNNELED is all it needs.
    if (provided < MPI_THREAD_FUNNELED)
      throw std::runtime_error("MPI: the library gives no MPI_THREAD_FUNNELED support (granmix's worker threads need it)");
    check(MPI_Comm_rank(MPI_COMM_WORLD, &w.rank), "MPI_Comm_rank");
    check(MPI_Comm_size(MPI_COMM_WORLD, &w.size), "MPI_Comm_size");
#else
    const char* n = std::getenv("OMPI_COMM_WORLD_SIZE");
    if (!n) n = std::getenv("PMI_SIZE");
    if (n && std::atoi(n) > 1)
      throw InputError("this granmix was built without MPI (GRANMIX_MPI=OFF) but started as " + std::string(n) +
                       " MPI ranks: each would run the whole job (allowed: one process, or an MPI build)");
#endif
    return w;
  }();
  started = &w;
  return w;
}

// Message tags between rank 0 and the others.
enum Tag : int { request = 1, unit_tag = 2, result = 3, failure = 4, bye = 5 };

struct Unit {
  std::size_t setup, replica;
  double cost;
};

std::vector<Unit> units_of(const std::vector<dsmc::DsmcSetup>& setups) {
  std::vector<Unit> u;
  for (std::size_t i = 0; i < setups.size(); ++i) {
    const double c = dsmc::estimated_collisions(setups[i]);
    for (std::size_t r = 0; r < setups[i].replicas; ++r) u.push_back({i, r, c});
  }
  // Longest first (list scheduling's LPT order); ties keep the plan's order, the same on every rank.
  std::stable_sort(u.begin(), u.end(), [](const Unit& a, const Unit& b) { return a.cost > b.cost; });
  return u;
}

// CPU time of the calling thread: a unit's cost that does not grow when the machine is shared.
double thread_cpu_seconds() {
  timespec ts{};
  if (clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts) != 0) throw std::runtime_error("clock_gettime(CLOCK_THREAD_CPUTIME_ID) failed");
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

#ifdef GRANMIX_MPI
// A finished unit as it travels: its index in the unit list, then the record (or an error text).
std::string pack(std::size_t index, double cpu, const dsmc::ReplicaRecord& r) {
  dsmc::ByteWriter w;
  w.put<std::uint64_t>(index);
  w.put(cpu);
  dsmc::write_record(w, r);
  return w.take();
}
#endif

// A queue of work or results between the main thread and the worker threads of one rank.
template <class T>
class Channel {
 public:
  void push(T x) {
    {
      std::lock_guard<std::mutex> l(m_);
      q_.push_back(std::move(x));
    }
    cv_.notify_one();
  }
  std::optional<T> try_pop() {
    std::lock_guard<std::mutex> l(m_);
    if (q_.empty()) return std::nullopt;
    T x = std::move(q_.front());
    q_.pop_front();
    return x;
  }
  // Blocks until an item or close(); nullopt once closed and empty.
  std::optional<T> pop() {
    std::unique_lock<std::mutex> l(m_);
    cv_.wait(l, [&] { return !q_.empty() || closed_; });
    if (q_.empty()) return std::nullopt;
    T x = std::move(q_.front());
    q_.pop_front();
    return x;
  }
  void close() {
    {
      std::lock_guard<std::mutex> l(m_);
      closed_ = true;
    }
    cv_.notify_all();
  }

 private:
  std::mutex m_;
  std::condition_variable cv_;
  std::deque<T> q_;
  bool closed_ = false;
};

struct Done {
  std::size_t index;
  dsmc::ReplicaRecord record;
  std::string error;  // empty: success
  double cpu = 0.0;   // CPU seconds of the thread that ran it
};

// Runs one unit, catching its error as text (a thread must not throw).
Done run_unit(const std::vector<dsmc::DsmcSetup>& setups, const std::vector<Unit>& units, std::size_t i) {
  Done d{i, {}, {}, 0.0};
  try {
    const double start = thread_cpu_seconds();
    d.record = dsmc::run_one_replica(setups[units[i].setup], units[i].replica);
    d.cpu = thread_cpu_seconds() - start;
  } catch (const std::exception& e) {
    d.error = e.what();
  }
  return d;
}

// One line on stderr, rewritten in place at most once a second on a terminal; off a terminal (a log, a pipe) none,
// unless GRANMIX_PROGRESS=1 asks for a line every 10% of the estimated work (GRANMIX_PROGRESS=0: none on a terminal
// either). The work done counts the replicas in flight too (their collisions so far, dsmc/progress_counter.hpp), so a
// run of one long replica moves before it ends; the time left scales the elapsed time by the estimated work left
// (dsmc/unit_cost.hpp: the units' costs are expected collisions).
class Progress {
 public:
  Progress(double total_cost, std::size_t units) : total_(total_cost), units_(units), tty_(isatty(STDERR_FILENO)) {
    const char* asked = std::getenv("GRANMIX_PROGRESS");
    shown_ = asked ? std::string(asked) != "0" : tty_;
  }
  void update(std::size_t done, double done_cost, double collisions, double elapsed) {
    if (!shown_) return;
    const double running = std::max<double>(0.0, double(dsmc::in_flight_collisions().total()));
    const double f = total_ > 0 ? std::min(1.0, (done_cost + running) / total_) : 1.0;
    if (!tty_ && f < next_ && done < units_) return;
    if (tty_ && elapsed - last_ < 1.0 && done < units_) return;
    last_ = elapsed, next_ = f + 0.1;
    const double left = f > 0 ? elapsed * (1.0 - f) / f : 0.0;
    std::fprintf(stderr, "%sDSMC: %zu/%zu units, %.0f%% of the estimated collisions, %.3g collisions/s, ~%.0f s left%s", tty_ ? "\r" : "",
                 done, units_, 100.0 * f, elapsed > 0 ? (collisions + running) / elapsed : 0.0, left, tty_ ? "   " : "\n");
    if (tty_ && done == units_) std::fprintf(stderr, "\n");
  }

 private:
  double total_;
  std::size_t units_;
  bool tty_, shown_;
  double last_ = -1.0, next_ = 0.1;
};

}  // namespace

int rank() { return world().rank; }
int ranks() { return world().size; }

int threads_per_rank(int requested) {
  if (requested > 0) return requested;
  const int cores = std::max(1u, std::thread::hardware_concurrency());
  const char* local = std::getenv("OMPI_COMM_WORLD_LOCAL_SIZE");
  const int per_node = world().mpi && local ? std::max(1, std::atoi(local)) : 1;
  return std::max(1, cores / per_node);
}

const dsmc::ReplicaRecord* GatheredReplicas::find(const std::string& unit_key, std::size_t replica) const {
  const auto it = records.find({unit_key, replica});
  return it == records.end() ? nullptr : &it->second;
}

void finish() {
#ifdef GRANMIX_MPI
  if (started && started->mpi) MPI_Finalize();  // at exit: nothing is left to report its code to
#endif
}

void abort(int code) {
#ifdef GRANMIX_MPI
  if (started && started->mpi && started->size > 1) MPI_Abort(MPI_COMM_WORLD, code);
#endif
  (void)code;
  finish();
}

std::string share_from_root(const std::string& text) {
#ifdef GRANMIX_MPI
  const World& w = world();
  if (!w.mpi || w.size == 1) return text;
  long long n = static_cast<long long>(text.size());
  check(MPI_Bcast(&n, 1, MPI_LONG_LONG, 0, MPI_COMM_WORLD), "MPI_Bcast (length)");
  std::string out = w.rank == 0 ? text : std::string(static_cast<std::size_t>(n), '\0');
  if (n > 0) check(MPI_Bcast(out.data(), static_cast<int>(n), MPI_CHAR, 0, MPI_COMM_WORLD), "MPI_Bcast (text)");
  return out;
#else
  return text;
#endif
}

GatheredReplicas run_units(const std::vector<dsmc::DsmcSetup>& setups, int threads) {
  const World& w = world();
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  const std::vector<Unit> units = units_of(setups);
  const int T = threads_per_rank(threads);
  GatheredReplicas out;
  out.ranks = w.size, out.threads = T;

  if (w.rank != 0) {
#ifdef GRANMIX_MPI
    // A worker rank: T threads compute what rank 0 hands out; this thread alone talks MPI.
    Channel<std::size_t> work;
    Channel<Done> finished;
    std::vector<std::thread> pool;
    for (int t = 0; t < T; ++t)
      pool.emplace_back([&] {
        while (auto i = work.pop()) finished.push(run_unit(setups, units, *i));
      });
    const int one = 1;
    for (int t = 0; t < T; ++t) check(MPI_Send(&one, 1, MPI_INT, 0, request, MPI_COMM_WORLD), "MPI_Send (request)");
    int slots = T, in_flight = 0;
    while (slots > 0 || in_flight > 0) {
      int flag = 0;
      check(MPI_Iprobe(0, unit_tag, MPI_COMM_WORLD, &flag, MPI_STATUS_IGNORE), "MPI_Iprobe");
      if (flag) {
        long long i = -1;
        check(MPI_Recv(&i, 1, MPI_LONG_LONG, 0, unit_tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE), "MPI_Recv (unit)");
        if (i < 0) --slots;
        else work.push(static_cast<std::size_t>(i)), ++in_flight;
        continue;
      }
      if (auto d = finished.try_pop()) {
        --in_flight;
        const std::string msg = d->error.empty() ? pack(d->index, d->cpu, d->record) : std::to_string(d->index) + "\n" + d->error;
        check(MPI_Send(msg.data(), static_cast<int>(msg.size()), MPI_BYTE, 0, d->error.empty() ? result : failure, MPI_COMM_WORLD),
              "MPI_Send (result)");
        check(MPI_Send(&one, 1, MPI_INT, 0, request, MPI_COMM_WORLD), "MPI_Send (request)");
        continue;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    work.close();
    for (auto& t : pool) t.join();
    check(MPI_Send(&one, 1, MPI_INT, 0, bye, MPI_COMM_WORLD), "MPI_Send (bye)");
#endif
    return out;
  }

  // Rank 0: hands out units in order to its own threads and, on request, to the other ranks.
  std::mutex m;
  std::size_t next = 0, done = 0;
  double done_cost = 0.0, collisions = 0.0, total_cost = 0.0;
  for (const Unit& u : units) total_cost += u.cost;
  std::vector<std::string> errors;
  std::vector<std::optional<dsmc::ReplicaRecord>> records(units.size());
  std::vector<int> where(units.size(), 0);
  std::vector<double> cpu(units.size(), 0.0);
  auto take = [&]() -> std::optional<std::size_t> {
    std::lock_guard<std::mutex> l(m);
    if (next >= units.size() || !errors.empty()) return std::nullopt;  // after a failure nothing new starts
    return next++;
  };
  auto store = [&](Done d, int from) {
    std::lock_guard<std::mutex> l(m);
    ++done, done_cost += units[d.index].cost;
    if (!d.error.empty()) {
      const dsmc::DsmcSetup& s = setups[units[d.index].setup];
      errors.push_back("replica " + std::to_string(units[d.index].replica) + " of " + (s.unit_key.empty() ? "a set-up" : s.unit_key) +
                       " (rank " + std::to_string(from) + "): " + d.error);
      return;
    }
    collisions += double(d.record.accepted);
    where[d.index] = from, cpu[d.index] = d.cpu;
    records[d.index] = std::move(d.record);
  };
  std::vector<std::thread> pool;
  for (int t = 0; t < T; ++t)
    pool.emplace_back([&] {
      while (auto i = take()) store(run_unit(setups, units, *i), 0);
    });
  std::fprintf(stderr, "DSMC: %zu units (replicas) of %zu ensembles on %d rank(s) x %d thread(s)\n", units.size(), setups.size(), w.size, T);
  Progress progress(total_cost, units.size());
  int byes = 0;
  for (;;) {
    std::size_t d;
    {
      std::lock_guard<std::mutex> l(m);
      d = done;
      progress.update(done, done_cost, collisions, elapsed());
    }
    const bool all_done = d == units.size() || (!errors.empty() && next == d);
    if (all_done && byes == w.size - 1) break;
#ifdef GRANMIX_MPI
    if (w.size > 1) {
      int flag = 0;
      MPI_Status st;
      check(MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &st), "MPI_Iprobe");
      if (flag) {
        int bytes = 0;
        check(MPI_Get_count(&st, MPI_BYTE, &bytes), "MPI_Get_count");
        std::string msg(static_cast<std::size_t>(bytes), '\0');
        check(MPI_Recv(msg.data(), bytes, MPI_BYTE, st.MPI_SOURCE, st.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE), "MPI_Recv");
        if (st.MPI_TAG == request) {
          const auto i = take();
          const long long v = i ? static_cast<long long>(*i) : -1;
          check(MPI_Send(&v, 1, MPI_LONG_LONG, st.MPI_SOURCE, unit_tag, MPI_COMM_WORLD), "MPI_Send (unit)");
        } else if (st.MPI_TAG == result) {
          dsmc::ByteReader in(msg);
          const auto i = static_cast<std::size_t>(in.get<std::uint64_t>());
          const double cpu = in.get<double>();
          store(Done{i, dsmc::read_record(in), {}, cpu}, st.MPI_SOURCE);
        } else if (st.MPI_TAG == failure) {
          const std::size_t cut = msg.find('\n');
          store(Done{std::stoul(msg.substr(0, cut)), {}, msg.substr(cut + 1), 0.0}, st.MPI_SOURCE);
        } else if (st.MPI_TAG == bye) {
          ++byes;
        }
        continue;
      }
    }
#endif
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  for (auto& t : pool) t.join();
  if (!errors.empty()) throw NumericalError("DSMC unit failed: " + errors.front());
  for (std::size_t i = 0; i < units.size(); ++i) {
    const dsmc::DsmcSetup& s = setups[units[i].setup];
    const dsmc::ReplicaRecord& r = *records[i];
    out.units.push_back({s.unit_key, units[i].replica, units[i].cost, double(r.accepted), cpu[i], where[i]});
    out.cpu_seconds += cpu[i];
    out.records.emplace(std::make_pair(s.unit_key, units[i].replica), std::move(*records[i]));
  }
  out.wall_seconds = elapsed();
  return out;
}

}  // namespace granmix::compare::scheduler
