#include "cluster/ranks.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <thread>

#include "util/cpus.h"
#include "util/error.h"

#ifdef GDR_HAVE_MPI
#include <mpi.h>
#endif

namespace gdr::cluster {
namespace {

int g_rank = 0, g_size = 1, g_local_rank = 0, g_local_size = 1;
[[maybe_unused]] bool g_mpi = false;  // MPI was initialized (and must be finalized)

std::string message_of(const std::exception_ptr& e) {
  try {
    std::rethrow_exception(e);
  } catch (const std::exception& x) {
    return x.what();
  } catch (...) {
    return "unknown error";
  }
}

#ifdef GDR_HAVE_MPI
bool started_by_launcher() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "PMI_RANK"}) {
    if (std::getenv(v)) return true;
  }
  return false;
}
#endif

}  // namespace

int launched_processes(const std::function<const char*(const char*)>& get) {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}) {
    const char* s = get(v);
    if (!s) continue;
    char* end = nullptr;
    long n = std::strtol(s, &end, 10);
    if (end != s && *end == '\0' && n > 1) return int(n);
  }
  return 1;
}

Session::Session(int& argc, char**& argv) {
#ifdef GDR_HAVE_MPI
  // Outside a launcher MPI is left alone: Open MPI's singleton start spawns a daemon, which the
  // single-process renderer has no use for.
  if (!started_by_launcher()) return;
  int provided = 0;
  // Only the main thread calls MPI (the render loop and the reductions run there).
  if (MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
    throw Error("MPI_Init_thread failed");
  }
  g_mpi = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &g_rank);
  MPI_Comm_size(MPI_COMM_WORLD, &g_size);
  MPI_Comm node;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, g_rank, MPI_INFO_NULL, &node);
  MPI_Comm_rank(node, &g_local_rank);
  MPI_Comm_size(node, &g_local_size);
  MPI_Comm_free(&node);
#else
  (void)argc;
  (void)argv;
  if (int n = launched_processes([](const char* v) { return std::getenv(v); }); n > 1) {
    throw Error("an MPI launcher started " + std::to_string(n) +
                " processes, but this gdrender was built without MPI: each would render the whole image and write "
                "the same files. Install libopenmpi-dev and openmpi-bin (scripts/setup.sh) and build again, or run "
                "it without mpirun");
  }
#endif
}

Session::~Session() {
#ifdef GDR_HAVE_MPI
  if (g_mpi) MPI_Finalize();
#endif
}

int rank() { return g_rank; }
int size() { return g_size; }
bool root() { return g_rank == 0; }
bool distributed() { return g_size > 1; }
int local_rank() { return g_local_rank; }
int local_size() { return g_local_size; }

std::string host() {
  char name[256] = {};
  if (gethostname(name, sizeof(name) - 1) != 0) return "unknown host";
  return name;
}

int cpu_share() {
  const int usable = usable_cpu_count();
  const int node = int(std::thread::hardware_concurrency());
  if (g_local_size <= 1 || node <= 0 || usable < node) return usable;
  return std::max(1, usable / g_local_size);
}

bool any(bool flag) {
#ifdef GDR_HAVE_MPI
  if (g_size > 1) {
    int in = flag ? 1 : 0, out = 0;
    MPI_Allreduce(&in, &out, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    return out != 0;
  }
#endif
  return flag;
}

void barrier() {
#ifdef GDR_HAVE_MPI
  if (g_size > 1) MPI_Barrier(MPI_COMM_WORLD);
#endif
}

std::vector<std::string> gather_to_root(const std::string& text) {
#ifdef GDR_HAVE_MPI
  if (g_size > 1) {
    int length = int(text.size());
    std::vector<int> lengths(g_rank == 0 ? g_size : 0), offsets;
    MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
    std::vector<char> all;
    if (g_rank == 0) {
      int total = 0;
      for (int n : lengths) offsets.push_back(total), total += n;
      all.resize(std::max(total, 1));
    }
    MPI_Gatherv(text.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(), MPI_CHAR, 0,
                MPI_COMM_WORLD);
    std::vector<std::string> out;
    for (int r = 0; r < int(lengths.size()); ++r) out.emplace_back(all.data() + offsets[r], size_t(lengths[r]));
    return out;
  }
#endif
  return {text};
}

void all_or_none(const std::function<void()>& setup) {
  if (g_size <= 1) {
    setup();
    return;
  }
  std::string error;
  try {
    setup();
  } catch (...) {
    error = message_of(std::current_exception());
    if (error.empty()) error = "failed";
  }
  // Every rank sends its host and reason (empty: it succeeded); rank 0 names each failure.
  std::vector<std::string> reports = gather_to_root(error.empty() ? std::string() : host() + "\n" + error);
  bool failed = any(!error.empty());
  if (!failed) return;
  for (int r = 0; r < int(reports.size()); ++r) {
    if (reports[r].empty()) continue;
    size_t cut = reports[r].find('\n');
    std::fprintf(stderr, "gdrender: rank %d of %d (%s): error: %s\n", r, g_size, reports[r].substr(0, cut).c_str(),
                 reports[r].substr(cut + 1).c_str());
  }
  throw JobFailed();
}

void check_same(const std::string& what, const std::string& value) {
  if (g_size <= 1) return;
  std::vector<std::string> values = gather_to_root(value);
  bool differ = false;
  for (int r = 1; r < int(values.size()); ++r) {
    if (values[r] == values[0]) continue;
    differ = true;
    std::fprintf(stderr, "gdrender: rank %d of %d: error: its %s (%s) differs from rank 0's (%s)\n", r, g_size,
                 what.c_str(), values[r].c_str(), values[0].c_str());
  }
  if (any(differ)) throw JobFailed();
}

bool stopped_early(bool stopped, const std::string& why) {
  if (g_size <= 1) return stopped;
  // "S" marks a rank that stopped, then its host and reason.
  std::vector<std::string> reports = gather_to_root(stopped ? "S" + host() + "\n" + why : std::string());
  if (!any(stopped)) return false;
  for (int r = 0; r < int(reports.size()); ++r) {
    const size_t cut = reports[r].find('\n');
    if (reports[r].empty() || cut + 1 == reports[r].size()) continue;
    std::fprintf(stderr, "gdrender: rank %d of %d (%s): %s\n", r, g_size, reports[r].substr(1, cut - 1).c_str(),
                 reports[r].substr(cut + 1).c_str());
  }
  return true;
}

void abort_job(const std::string& message) {
  std::fprintf(stderr, "gdrender: rank %d of %d (%s): error: %s\n", g_rank, g_size, host().c_str(), message.c_str());
  std::fflush(stderr);
#ifdef GDR_HAVE_MPI
  if (g_mpi) MPI_Abort(MPI_COMM_WORLD, 1);
#endif
  std::_Exit(1);
}

}  // namespace gdr::cluster
