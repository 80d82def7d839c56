#pragma once
// Element loops on all cores, with the same bits for any thread count (issue 50). Each element's work is
// done on whichever thread OpenMP hands it to and written to a place of its own (its state, its slot of
// a buffer); whatever adds elements together (a global force vector, a dissipation) does so afterwards,
// in element order, so that every sum is made in the order of a one-thread loop: on one thread, or on
// threads where each sum has an owner of its own (a global equation, gathered node by node from the
// elements on its node in element order: CohesiveInterface). A sum that no one-thread loop fixes (an
// energy of the mass) is made in fixed chunks, added in chunk order: the same bits for any thread count.
//
// The threads are those of the calling thread's OpenMP setting (omp_set_num_threads; all cores unless
// OMP_NUM_THREADS says otherwise): a run sets it from its request (ImpactCase::run), a sweep's worker
// threads set it to one (they are the sweep's parallelism).
#include <Eigen/Core>
#include <omp.h>

#include <algorithm>
#include <exception>
#include <thread>

namespace plyimpact {

/// work(i) for i = 0 … count − 1 on the calling thread's OpenMP threads; the calls must be independent of
/// each other. An exception thrown by work(i) is rethrown here, that of the smallest i where several
/// throw (the one a one-thread loop would have met first).
template <class Work>
void for_each_element(int count, const Work& work) {
  std::exception_ptr error;
  int error_at = count;
  // About 16 chunks per thread: enough to even out elements of unequal cost (damaged points, contact),
  // few enough that handing them out costs little next to their work.
  const int per_fetch = std::max(1, count / (16 * omp_get_max_threads()));
#pragma omp parallel for schedule(dynamic, per_fetch)
  for (int i = 0; i < count; ++i) {
    try {
      work(i);
    } catch (...) {
#pragma omp critical(plyimpact_element_loop_error)
      if (i < error_at) {
        error_at = i;
        error = std::current_exception();
      }
    }
  }
  if (error) std::rethrow_exception(error);
}

/// The indices first … last − 1 of block `block` of `blocks` equal blocks of 0 … n − 1.
struct IndexRange {
  Eigen::Index first, last;
};
[[nodiscard]] constexpr IndexRange block_range(Eigen::Index n, int block, int blocks) {
  return {n * block / blocks, n * (block + 1) / blocks};
}

/// The blocks of rows, entries or nodes that the loops below hand to the threads: fixed, so that a block's
/// sums are the same whatever thread makes them; enough to even out two to sixteen threads.
constexpr int fixed_blocks = 64;

/// work(first, last) for each of `blocks` fixed blocks of the indices 0 … n − 1 (block_range), on the
/// calling thread's threads. Where each result is written by the block that owns it and summed inside it,
/// the bits are those of one thread for any number of threads.
template <class Work>
void for_each_block(Eigen::Index n, const Work& work, int blocks = fixed_blocks) {
  for_each_element(blocks, [&](int b) {
    const IndexRange r = block_range(n, b, blocks);
    work(r.first, r.last);
  });
}

/// Vectors shorter than this are updated in one call by elementwise_on_threads: a parallel region costs
/// a few microseconds, the update of 16 384 entries about as much.
constexpr Eigen::Index elementwise_threshold = 16384;

/// work(first, last) over the indices 0 … n − 1 for work that writes each index from that index alone (an
/// elementwise vector update, no sum across indices): in for_each_block's fixed blocks on the calling
/// thread's threads where n reaches `threshold`, in one call below it or on one thread. Each entry is
/// computed by the same operations either way: the same bits.
template <class Work>
void elementwise_on_threads(Eigen::Index n, const Work& work,
                            Eigen::Index threshold = elementwise_threshold) {
  if (n < threshold || omp_get_max_threads() == 1)
    work(Eigen::Index{0}, n);
  else
    for_each_block(n, work);
}

/// x = d ∘ r (entry by entry), through elementwise_on_threads: the numbers of `x = d.cwiseProduct(r)`.
inline void parallel_cwise_product(const Eigen::VectorXd& d, const Eigen::VectorXd& r, Eigen::VectorXd& x) {
  x.resize(r.size());
  elementwise_on_threads(r.size(), [&](Eigen::Index first, Eigen::Index last) {
    x.segment(first, last - first) =
        d.segment(first, last - first).cwiseProduct(r.segment(first, last - first));
  });
}

/// out = K u for a row-major sparse K, blocks of rows on the calling thread's threads: each row's sum is
/// made as in a one-thread product, so the bits are those of `out = K * u` for any number of threads.
template <class RowMajorSparse>
void parallel_rows_product(const RowMajorSparse& K, const Eigen::VectorXd& u, Eigen::VectorXd& out) {
  out.resize(K.rows());
  for_each_block(K.rows(), [&](Eigen::Index first, Eigen::Index last) {
    out.segment(first, last - first).noalias() = K.middleRows(first, last - first) * u;
  });
}

/// The number of threads for_each_element uses from the calling thread (the size of per-thread scratch).
[[nodiscard]] inline int element_threads() {
  return omp_get_max_threads();
}

/// The threads the machine runs at once (at least 1): no element loop asks for more (issue 77: libgomp
/// crashed starting the 100 000 threads that OMP_NUM_THREADS=100000 asked for).
[[nodiscard]] inline int hardware_threads() {
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

/// `threads` (0: the calling thread's OpenMP setting, OMP_NUM_THREADS or all cores) capped to the machine.
[[nodiscard]] inline int capped_threads(int threads) {
  return std::min(threads > 0 ? threads : omp_get_max_threads(), hardware_threads());
}

/// The element loops of the calling thread on `threads` threads while it lives (0: as they are), never
/// more than the machine has (capped_threads), as they were after it.
class ElementThreads {
public:
  explicit ElementThreads(int threads) : previous_(capped_threads(0)) {
    omp_set_num_threads(capped_threads(threads));
  }
  ~ElementThreads() { omp_set_num_threads(previous_); }
  ElementThreads(const ElementThreads&) = delete;
  ElementThreads& operator=(const ElementThreads&) = delete;
  ElementThreads(ElementThreads&&) = delete;
  ElementThreads& operator=(ElementThreads&&) = delete;

private:
  int previous_;
};

} // namespace plyimpact
