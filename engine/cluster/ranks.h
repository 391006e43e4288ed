// The processes of one render started under MPI (`mpirun -np N gdrender ...`): rank r of N, each
// rendering its share of the passes (render/pass_schedule.h). A process not started by an MPI
// launcher, or built without MPI, is rank 0 of 1, and every call here is then a no-op or the
// identity: the single-process renderer runs exactly as before, without initializing MPI.
#pragma once
#include <functional>
#include <string>
#include <vector>

namespace gdr::cluster {

// MPI for the process's lifetime: initialized on construction when an MPI launcher started the
// process (an MPI build only), finalized on destruction. Throws Error when a launcher started N > 1
// copies of a build without MPI: each would render the whole image and write the same files.
class Session {
 public:
  Session(int& argc, char**& argv);
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;
};

int rank();
int size();
bool root();                 // rank 0: the one that reconstructs, writes and reports
bool distributed();          // size() > 1
int local_rank();            // rank among the processes on this node
int local_size();
std::string host();          // this node's name

// The CPUs this process should use: those of its affinity mask when the launcher bound it to a
// subset of the node (mpirun's default), else its share of the node's (all of them alone).
int cpu_share();

// The launcher's environment says how many processes it started (OMPI_COMM_WORLD_SIZE of Open
// MPI's mpirun, PMI_SIZE of MPICH's); 1 when none did. `get` reads a variable (getenv).
int launched_processes(const std::function<const char*(const char*)>& get);

// True on every rank when `flag` is true on any (a collective: every rank calls it).
bool any(bool flag);
void barrier();

// Runs `setup` on every rank and then agrees on its outcome: when a rank throws, rank 0 prints
// each failing rank's reason (naming the rank and its host) and every rank throws JobFailed, so
// that no rank waits for one that is gone. Alone, the exception passes through unchanged.
void all_or_none(const std::function<void()>& setup);

// True on every rank when `stopped` is true on any (a collective); rank 0 then prints, for each
// rank that stopped with a non-empty `why`, its rank, host and `why`. Alone: `stopped`.
bool stopped_early(bool stopped, const std::string& why);

// Checks that every rank has the same `value` (what it is about to do): where one differs, rank 0
// prints that rank's and its own `what` and every rank throws JobFailed. Alone: nothing.
void check_same(const std::string& what, const std::string& value);

// Thrown on every rank when all_or_none found a failure; rank 0 has printed the reasons.
class JobFailed : public std::exception {
 public:
  const char* what() const noexcept override { return "a rank failed"; }
};

// Ends the whole job at once after printing `message` with this rank's name: for an error on one
// rank after the ranks have started rendering, when the others may be waiting for it.
[[noreturn]] void abort_job(const std::string& message);

// `text` of every rank, on rank 0 (index = rank); empty elsewhere.
std::vector<std::string> gather_to_root(const std::string& text);

}  // namespace gdr::cluster
