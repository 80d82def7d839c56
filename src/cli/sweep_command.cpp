#include "sweep_command.hpp"

#include "plyimpact/io/deck/deck.hpp"
#include "plyimpact/io/results/output_folder.hpp"
#include "plyimpact/io/sweeps/sweep_runner.hpp"
#include "plyimpact/io/system/environment.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>

#ifdef PLYIMPACT_HAVE_MPI
#include <mpi.h>
#endif

namespace plyimpact {

namespace {

/// Started by mpirun or srun: Open MPI, PMI and PMIx launchers set one of these.
bool launched_by_mpi() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE", "PMI_RANK"})
    if (std::getenv(name) != nullptr) return true;
  return false;
}

/// The process's place in a run: one process without MPI, or an MPI rank.
class Ranks {
public:
  virtual ~Ranks() = default;
  [[nodiscard]] virtual int rank() const { return 0; }
  [[nodiscard]] virtual int size() const { return 1; }
  virtual void barrier() {}
  [[nodiscard]] virtual long sum(long local) { return local; }
  /// Positions [0, count) handed out dynamically to every worker thread of every rank.
  [[nodiscard]] virtual NextCase dispenser(std::size_t count) {
    return [this, count]() -> std::optional<std::size_t> {
      const std::size_t p = next_++;
      if (p < count) return p;
      return std::nullopt;
    };
  }
  /// After this rank's workers are done: rank 0 waits until every other rank has left.
  virtual void finish_dispensing() {}
  [[noreturn]] virtual void abort(int code) { std::exit(code); }

protected:
  std::atomic<std::size_t> next_{0};
};

#ifdef PLYIMPACT_HAVE_MPI
/// MPI ranks. Rank 0 owns the case counter: its workers take positions directly, a service thread
/// answers the other ranks' requests; the other ranks' workers ask rank 0 one at a time
/// (MPI_THREAD_SERIALIZED is enough). Each rank writes its own case records.
class MpiRanks final : public Ranks {
public:
  MpiRanks() {
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_SERIALIZED, &provided);
    if (provided < MPI_THREAD_SERIALIZED) {
      MPI_Finalize();
      throw std::runtime_error("sweep: the MPI library does not support MPI_THREAD_SERIALIZED");
    }
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }
  ~MpiRanks() override {
    if (service_.joinable()) service_.join();
    MPI_Finalize();
  }
  MpiRanks(const MpiRanks&) = delete;
  MpiRanks& operator=(const MpiRanks&) = delete;

  [[nodiscard]] int rank() const override { return rank_; }
  [[nodiscard]] int size() const override { return size_; }
  /// A barrier that sleeps while it waits: a rank done early must not spin on a core its
  /// neighbours still compute on (MPI_Barrier busy-polls in Open MPI).
  void barrier() override {
    MPI_Request request = MPI_REQUEST_NULL;
    MPI_Ibarrier(MPI_COMM_WORLD, &request);
    for (int done = 0;;) {
      MPI_Test(&request, &done, MPI_STATUS_IGNORE);
      if (done != 0) return;
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  }
  [[nodiscard]] long sum(long local) override {
    long total = 0;
    MPI_Allreduce(&local, &total, 1, MPI_LONG, MPI_SUM, MPI_COMM_WORLD);
    return total;
  }
  [[noreturn]] void abort(int code) override {
    MPI_Abort(MPI_COMM_WORLD, code);
    std::exit(code);
  }

  [[nodiscard]] NextCase dispenser(std::size_t count) override {
    if (rank_ == 0) {
      if (size_ > 1) service_ = std::thread([this, count] { serve(count); });
      return Ranks::dispenser(count);
    }
    return [this]() -> std::optional<std::size_t> {
      const std::lock_guard lock(mutex_);
      if (exhausted_) return std::nullopt;
      int request = 0;
      long position = -1;
      MPI_Send(&request, 1, MPI_INT, 0, tag_request, MPI_COMM_WORLD);
      MPI_Recv(&position, 1, MPI_LONG, 0, tag_reply, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      if (position < 0) {
        exhausted_ = true;
        return std::nullopt;
      }
      return static_cast<std::size_t>(position);
    };
  }

  void finish_dispensing() override {
    if (rank_ == 0) {
      if (service_.joinable()) service_.join();
      return;
    }
    int leave = 0;
    MPI_Send(&leave, 1, MPI_INT, 0, tag_leave, MPI_COMM_WORLD);
  }

private:
  static constexpr int tag_request = 71, tag_reply = 72, tag_leave = 73;

  /// Rank 0's service thread: next position (or −1) for each request, until every rank has left.
  void serve(std::size_t count) {
    int left = 0;
    while (left < size_ - 1) {
      int flag = 0;
      MPI_Status status;
      MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status);
      if (flag == 0) { // idle: poll gently; a case takes a tenth of a second or more
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
        continue;
      }
      int payload = 0;
      MPI_Recv(&payload, 1, MPI_INT, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      if (status.MPI_TAG == tag_leave) {
        ++left;
        continue;
      }
      const std::size_t p = next_++;
      const long position = p < count ? static_cast<long>(p) : -1L;
      MPI_Send(&position, 1, MPI_LONG, status.MPI_SOURCE, tag_reply, MPI_COMM_WORLD);
    }
  }

  int rank_ = 0, size_ = 1;
  std::thread service_;
  std::mutex mutex_;
  bool exhausted_ = false;
};
#endif

std::unique_ptr<Ranks> make_ranks() {
  if (!launched_by_mpi()) return std::make_unique<Ranks>();
#ifdef PLYIMPACT_HAVE_MPI
  return std::make_unique<MpiRanks>();
#else
  throw std::runtime_error("sweep: started by an MPI launcher, but this plyimpact was built without MPI "
                           "(install libopenmpi-dev and rebuild)");
#endif
}

std::optional<SweepMode> mode_option(const std::string& mode) {
  if (mode.empty()) return std::nullopt;
  return mode == "zip" ? SweepMode::zip : SweepMode::product;
}

std::optional<AnalysisKind> analysis_option(const std::string& analysis) {
  if (analysis.empty()) return std::nullopt;
  return parse_analysis_kind(analysis);
}

/// --strict: every case's deck is read before anything runs, and the first plausibility warnings
/// (docs/deck.md) stop the sweep.
void refuse_implausible_cases(const Sweep& sweep) {
  std::string found;
  std::size_t cases = 0;
  for (std::size_t i = 0; i < sweep.size(); ++i) {
    const Deck deck = sweep.deck_for(sweep.case_at(i));
    if (deck.warnings.empty()) continue;
    if (++cases <= 3) found += fmt::format("\n  case {}: {}", i + 1, deck.warnings.front());
  }
  if (cases > 0)
    throw DeckError(fmt::format("{}: error: {} of {} cases have implausible values, refused by --strict:{}",
                                sweep.source(), cases, sweep.size(), found));
}

/// "case N: <error>" of the first case whose record holds an error, for the message of a sweep in which
/// no case completed.
std::string first_error(const SweepFolder& folder, std::size_t cases) {
  for (std::size_t i = 0; i < cases; ++i)
    if (const auto record = folder.read_record(i);
        record && record->contains("error") && record->at("error").is_string())
      return fmt::format("case {}: {}", i, record->at("error").get<std::string>());
  return "no error recorded";
}

/// Everything after MPI start-up; collective steps in the same order on every rank.
int run_sweep(Ranks& ranks, const SweepCommandOptions& o, const std::atomic<bool>& interrupted) {
  const auto t0 = std::chrono::steady_clock::now();
  const bool root = ranks.rank() == 0;
  // Every rank reads the same deck and folder, so a bad spec stops every rank alike.
  const Sweep sweep = Sweep::load(o.deck_path, o.set, mode_option(o.mode), analysis_option(o.analysis));
  if (o.strict) refuse_implausible_cases(sweep);
  // -o, else <[output] dir>/<deck name>/ as for the other commands (docs/output.md)
  const std::filesystem::path dir = o.output_dir.empty()
                                        ? default_output_dir(load_deck(o.deck_path).output_dir, o.deck_path)
                                        : std::filesystem::path(o.output_dir);
  const SweepFolder folder(dir, sweep);
  // Rank 0 locks the folder for the whole sweep (another sweep or run into it is refused) and checks
  // what it holds; the other ranks learn the outcome and stop alike.
  std::optional<OutputLock> lock;
  std::string refusal;
  if (root) try {
      ClaimOptions claim{o.overwrite, {}};
      if (!o.overwrite) claim.keep = SweepFolder::resumable_results();
      lock.emplace(claim_output_folder(dir, o.command, claim));
      fmt::print("results: {}\n", dir.string());
      if (const auto warning = folder.check(o.resume))
        fmt::print(stderr, "plyimpact: warning: {}\n", *warning);
    } catch (const std::exception& e) {
      refusal = e.what();
    }
  if (ranks.sum(refusal.empty() ? 0 : 1) > 0) {
    if (root) throw std::runtime_error(refusal);
    return 1;
  }
  if (root) folder.write_manifest();
  ranks.barrier();
  const SweepFolder::Pending scanned = folder.scan();
  const std::vector<std::size_t>& pending = scanned.cases;
  if (root)
    for (const std::string& d : scanned.damaged)
      fmt::print(stderr, "plyimpact: warning: {}\n", d);
  ranks.barrier(); // every rank has the same list before any record is written
  const int jobs =
      o.jobs > 0
          ? o.jobs
          : (ranks.size() > 1 ? 1 : static_cast<int>(std::max(1U, std::thread::hardware_concurrency())));
  if (root)
    fmt::print("sweep: {} cases ({} to run) on {} rank{} x {} thread{}, {} analysis\n", sweep.size(),
               pending.size(), ranks.size(), ranks.size() > 1 ? "s" : "", jobs, jobs > 1 ? "s" : "",
               to_string(sweep.spec().analysis));
  std::fflush(stdout);
  SweepOptions options;
  options.case_folders = o.case_folders;
  options.share_factorization = !o.no_sharing;
  options.cancel = &interrupted;
  // Progress of this process's cases. Under MPI every rank reports its own share (the dispenser
  // balances the ranks, so the share is about pending / ranks), as lines that carry the rank.
  const ProgressStyle style =
      ranks.size() > 1 && !o.progress.quiet ? ProgressStyle::lines : progress_style(o.progress, stderr);
  const std::size_t share = (pending.size() + ranks.size() - 1) / ranks.size();
  Progress progress(ranks.size() > 1 ? fmt::format("sweep rank {} of {}", ranks.rank(), ranks.size())
                                     : "sweep",
                    static_cast<double>(share), style, o.progress.line_interval_s);
  std::atomic<std::size_t> recorded{0};
  options.on_case_recorded = [&] {
    const std::size_t done = ++recorded;
    progress.update(static_cast<double>(done), fmt::format("{} of {} cases", done, share));
  };
  int local_factorizations = 0;
  try {
    const NextCase next = ranks.dispenser(pending.size());
    local_factorizations = run_sweep_cases(sweep, folder, pending, jobs, next, options);
    ranks.finish_dispensing();
  } catch (const std::exception& e) {
    fmt::print(stderr, "plyimpact: error: rank {}: {}\n", ranks.rank(), e.what());
    ranks.abort(1);
  }
  progress.finish(fmt::format("{} case{} recorded", recorded.load(), recorded.load() == 1 ? "" : "s"));
  ranks.barrier(); // sleeps while the slowest rank finishes its last case
  const long factorizations = ranks.sum(local_factorizations);
  if (!root) return interrupted.load() ? 130 : 0;
  const SweepFolder::TableStatus status = folder.write_table();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  // The cases this run actually recorded: an interrupted sweep says how far it got.
  const std::size_t finished = pending.size() - std::min<std::size_t>(status.missing, pending.size());
  fmt::print("sweep: {} of {} cases run in {:.3f} s ({:.3f} cases/s), {} factorization{} of K\n", finished,
             pending.size(), wall, static_cast<double>(finished) / wall, factorizations,
             factorizations == 1 ? "" : "s");
  if (status.missing > 0) {
    fmt::print(stderr, "plyimpact: {} of {} cases have no record: run again with --resume\n", status.missing,
               sweep.size());
    return interrupted.load() ? 130 : 3;
  }
  fmt::print("sweep: table {}\n", (folder.path() / "sweep.csv").string());
  if (status.failed == sweep.size()) { // nothing usable: a script must not take it for a good run
    fmt::print(stderr,
               "plyimpact: error: none of the {} cases completed (status and error columns of {}); {}\n",
               sweep.size(), (folder.path() / "sweep.csv").string(), first_error(folder, sweep.size()));
    return 1;
  }
  if (status.failed > 0)
    fmt::print(stderr, "plyimpact: warning: {} of {} cases did not complete (status and error columns)\n",
               status.failed, sweep.size());
  return 0;
}

} // namespace

CLI::App* add_sweep_command(CLI::App& app, SweepCommandOptions& o) {
  CLI::App* sub =
      app.add_subcommand("sweep", "Parameter study: many decks from one ([sweep] table or --set), "
                                  "on all cores and MPI ranks, resumable");
  sub->add_option("deck", o.deck_path, "base TOML deck, with an optional [sweep] table")->required();
  sub->add_option("-o,--output", o.output_dir,
                  "results folder: sweep.csv, sweep.json, cases/ (default: results/<deck name>)");
  sub->add_option("--set", o.set,
                  "KEY=V1,V2,... or KEY=start:stop:count (repeatable), e.g. impactor.velocity=1,2")
      ->allow_extra_args(false);
  sub->add_option("--mode", o.mode, "product (every combination, default) or zip (lists in step)")
      ->check(CLI::IsMember({"product", "zip"}));
  sub->add_option("--analysis", o.analysis,
                  "impact or threshold (default: [sweep] analysis, else the deck's)")
      ->check(CLI::IsMember({"impact", "threshold"}));
  sub->add_option("-j,--jobs", o.jobs, "threads per process (default: all cores; 1 per MPI rank)")
      ->check(CLI::Range(1, max_sweep_jobs));
  sub->add_flag("--resume", o.resume, "run only the cases without a record in DIR/cases");
  sub->add_flag("--overwrite", o.overwrite, "replace the results of another run or sweep in the folder");
  sub->add_flag("--case-folders", o.case_folders, "also write DIR/cases/NNNNNN/ with each case's results");
  sub->add_flag("--no-sharing", o.no_sharing, "factor K for every case (to measure what sharing saves)");
  sub->add_flag("--strict", o.strict,
                "refuse the sweep when a case's deck has implausible values (unit slips)");
  add_progress_options(*sub, o.progress);
  return sub;
}

/// Seconds between progress lines: a finite number from 0 to a day (NaN, inf and negatives refused; CLI11's
/// NonNegativeNumber let "nan" through, issue 77).
CLI::Validator progress_interval() {
  return {[](const std::string& text) -> std::string {
            if (text == "0") return "";
            const std::optional<double> value = positive_number(text);
            if (value && *value <= 86400.0) return "";
            return "must be a number of seconds from 0 to 86400, got " + text;
          },
          "SECONDS"};
}

void add_progress_options(CLI::App& sub, ProgressSettings& progress) {
  sub.add_flag("-q,--quiet", progress.quiet, "no progress display on stderr");
  sub.add_option("--progress-every", progress.line_interval_s,
                 "seconds between progress lines when stderr is not a terminal (default 10)")
      ->check(progress_interval());
}

int run_sweep_command(const SweepCommandOptions& o, const std::atomic<bool>& interrupted) {
  const std::unique_ptr<Ranks> ranks = make_ranks();
  return run_sweep(*ranks, o, interrupted);
}

} // namespace plyimpact
