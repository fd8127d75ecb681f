// An experiment spread over the ranks of an MPI run (`mpirun -np K
// openswarm experiment FILE`, or `srun` under Slurm): each rank runs every
// K-th trial, and rank 0 gathers the results and writes them. Launched
// without MPI, the tool is one rank of one.
#pragma once

#include <string>
#include <vector>

namespace openswarm {

// One trial's outcome as it travels: its samples (time, largest cluster,
// compactness, three doubles each) or why it failed.
struct TrialOutcome {
    std::vector<double> samples;
    std::string failure;
    bool here = false; // run by this rank
};

class Ranks {
  public:
    // Joins the MPI run the process was launched in, if any.
    Ranks();
    ~Ranks();
    Ranks(const Ranks &) = delete;
    Ranks &operator=(const Ranks &) = delete;

    int rank() const { return rank_; }
    int size() const { return size_; }
    // Ranks on this machine (to share its cores among them).
    int local_size() const { return local_size_; }
    bool mine(size_t slot) const { return (int)(slot % (size_t)size_) == rank_; }
    // Every job's outcome on rank 0, from the rank that ran it (its
    // outcome marked here); other ranks' vectors are left as they are.
    void gather(std::vector<TrialOutcome> &outcomes) const;
    // Returns when every rank has come here (a sweep's trials are on a
    // shared disk: rank 0 reads them after).
    void barrier() const;
    // Rank 0's exit status, for every rank to return.
    int agree(int status) const;

  private:
    int rank_ = 0, size_ = 1, local_size_ = 1;
    bool mpi_ = false;
};

}  // namespace openswarm
