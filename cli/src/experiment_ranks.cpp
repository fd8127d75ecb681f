#include "experiment_ranks.hpp"

#include <cstdlib>

#include <mpi.h>

#include "experiment_failures.hpp"

namespace openswarm {

namespace {

// Launched by mpirun (Open MPI) or srun (PMIx, PMI): the environment says.
bool launched_by_mpi() {
    return std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMIX_RANK") || std::getenv("PMI_SIZE");
}

int env_int(const char *name, int fallback) {
    const char *v = std::getenv(name);
    return v ? std::atoi(v) : fallback;
}

// A rank's outcomes in two messages: doubles (job, count, samples...) and
// the failures' reasons (experiment_failures.hpp).
void send(const std::vector<TrialOutcome> &outcomes) {
    std::vector<double> numbers;
    for (size_t k = 0; k < outcomes.size(); k++) {
        if (!outcomes[k].here) continue;
        numbers.push_back((double)k);
        numbers.push_back((double)outcomes[k].samples.size());
        numbers.insert(numbers.end(), outcomes[k].samples.begin(), outcomes[k].samples.end());
    }
    const std::string failures = encode_failures(outcomes);
    MPI_Send(numbers.data(), (int)numbers.size(), MPI_DOUBLE, 0, 1, MPI_COMM_WORLD);
    MPI_Send(failures.data(), (int)failures.size(), MPI_CHAR, 0, 2, MPI_COMM_WORLD);
}

void receive(std::vector<TrialOutcome> &outcomes, int from) {
    MPI_Status status;
    int count = 0;
    MPI_Probe(from, 1, MPI_COMM_WORLD, &status);
    MPI_Get_count(&status, MPI_DOUBLE, &count);
    std::vector<double> numbers((size_t)count);
    MPI_Recv(numbers.data(), count, MPI_DOUBLE, from, 1, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    std::vector<size_t> sent; // the trials rank from ran
    for (size_t at = 0; at + 2 <= numbers.size();) {
        size_t k = (size_t)numbers[at], n = (size_t)numbers[at + 1];
        outcomes[k].samples.assign(numbers.begin() + (long)at + 2, numbers.begin() + (long)(at + 2 + n));
        sent.push_back(k);
        at += 2 + n;
    }
    MPI_Probe(from, 2, MPI_COMM_WORLD, &status);
    MPI_Get_count(&status, MPI_CHAR, &count);
    std::string failures((size_t)count, '\0');
    MPI_Recv(failures.data(), count, MPI_CHAR, from, 2, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    std::string why;
    if (decode_failures(failures, outcomes, why)) return;
    // Not from this version of the tool: the rank's trials without samples
    // failed for a reason rank 0 cannot read, rather than seem to have run.
    for (size_t k : sent)
        if (outcomes[k].samples.empty() && outcomes[k].failure.empty())
            outcomes[k].failure = "rank " + std::to_string(from) + " sent why it failed in a form rank 0 "
                                  "cannot read (" + why + "): run every rank with the same openswarm";
}

}  // namespace

Ranks::Ranks() {
    if (!launched_by_mpi()) return;
    MPI_Init(nullptr, nullptr);
    mpi_ = true;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
    local_size_ = env_int("OMPI_COMM_WORLD_LOCAL_SIZE", env_int("SLURM_NTASKS_PER_NODE", 1));
    if (local_size_ < 1) local_size_ = 1;
}

Ranks::~Ranks() {
    if (mpi_) MPI_Finalize();
}

void Ranks::gather(std::vector<TrialOutcome> &outcomes) const {
    if (!mpi_ || size_ == 1) return;
    if (rank_ != 0) {
        send(outcomes);
        return;
    }
    for (int from = 1; from < size_; from++) receive(outcomes, from);
}

void Ranks::barrier() const {
    if (mpi_) MPI_Barrier(MPI_COMM_WORLD);
}

int Ranks::agree(int status) const {
    if (mpi_) MPI_Bcast(&status, 1, MPI_INT, 0, MPI_COMM_WORLD);
    return status;
}

}  // namespace openswarm
