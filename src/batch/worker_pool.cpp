// A batch's runs in persistent workers or one process per run (worker_pool.hpp).
#include "batch/worker_pool.hpp"

#include <memory>
#include <utility>

#include "batch/worker_process.hpp"

namespace signalsim {
namespace {

// One process per run: the job's own `signalsim run`, which takes no other run.
class OneRunProcess : public SupervisedChild {
 public:
  explicit OneRunProcess(const ProcessJob& job) : process_(ChildProcess::start({job.argv, {}, nullptr})) {}
  ChildProcess& process() override { return process_; }
  const ChildProcess& process() const override { return process_; }
  bool take_run(const ProcessJob&) override { return !std::exchange(took_run_, true); }

 private:
  ChildProcess process_;
  bool took_run_ = false;
};

}  // namespace

bool run_in_workers(const std::vector<ProcessJob>& jobs, int parallel,
                    const std::function<void(const ProcessJob&, const ProcessResult&)>& on_done,
                    const std::function<void()>& on_tick) {
  Supervision how;
  how.make_child = [](const ProcessJob& job) { return std::make_unique<WorkerProcess>(job.argv.front()); };
  how.child_noun = "worker";
  how.on_done = on_done;
  how.on_tick = on_tick;
  return supervise(jobs, parallel, how);
}

bool run_processes(const std::vector<ProcessJob>& jobs, int parallel,
                   const std::function<void(const ProcessJob&, const ProcessResult&)>& on_done,
                   const std::function<void()>& on_tick) {
  Supervision how;
  how.make_child = [](const ProcessJob& job) { return std::make_unique<OneRunProcess>(job); };
  how.child_noun = "process";
  how.on_done = on_done;
  how.on_tick = on_tick;
  return supervise(jobs, parallel, how);
}

bool run_jobs(const std::vector<ProcessJob>& jobs, int parallel, bool isolate,
              const std::function<void(const ProcessJob&, const ProcessResult&)>& on_done,
              const std::function<void()>& on_tick) {
  if (isolate) return run_processes(jobs, parallel, on_done, on_tick);
  return run_in_workers(jobs, parallel, on_done, on_tick);
}

}  // namespace signalsim
