// sbatch, squeue, scancel and scontrol as functions (slurm_commands.hpp).
#include "batch/slurm/slurm_commands.hpp"

#include <stdexcept>

#include "batch/run_rows.hpp"
#include "batch/slurm/program_output.hpp"

namespace signalsim {

void require_slurm_programs(const std::vector<std::string>& programs) {
  for (const std::string& program : programs)
    if (find_on_path(program).empty())
      throw std::runtime_error("--backend slurm: " + program +
                               " is not on PATH (install slurm-client, or load the cluster's Slurm module)");
}

void require_slurm_controller() {
  const ProgramOutput out = run_program({"scontrol", "ping"}, {}, kSlurmPingTimeout);
  if (out.started && out.exit_code == 0) return;
  std::string why;
  if (out.timed_out) {
    why = "scontrol ping " + out.err;
  } else if (!out.started) {
    why = "scontrol: " + out.err;
  } else {
    // "Slurmctld(primary) at HOST is DOWN" and a banner of asterisks; or scontrol's error lines.
    const std::string first = out.out.substr(0, out.out.find('\n'));
    why = "scontrol ping: " + (first.find(" is DOWN") != std::string::npos ? first
                                                                          : stderr_one_line(out.err.empty() ? out.out : out.err));
  }
  throw std::runtime_error("--backend slurm: no Slurm controller answers (" + why + ")");
}

std::string output_pattern(const std::string& directory, const std::string& name) {
  // sbatch's --output is a filename pattern (%j, %A, %a, ... replaced; "%%" is a '%'), made
  // absolute with the task's directory before it is expanded, so a relative name and --chdir
  // would not keep the user's path out of it either.
  if (directory.find('\\') != std::string::npos)
    throw std::runtime_error("--backend slurm: --out " + directory.substr(0, directory.rfind("/slurm/logs")) +
                             " holds a '\\', with which sbatch names every task's log alike (no %A/%a "
                             "patterns): choose an --out without it");
  std::string out;
  for (const char c : directory) out += c == '%' ? std::string("%%") : std::string(1, c);
  return out + "/" + name;
}

std::vector<std::string> sbatch_argv(const ArraySubmission& s) {
  std::vector<std::string> argv = {"sbatch", "--parsable", "--job-name=" + s.job_name,
                                   "--array=0-" + std::to_string(s.tasks - 1) +
                                       (s.max_parallel > 0 ? "%" + std::to_string(s.max_parallel) : ""),
                                   "--cpus-per-task=" + std::to_string(s.cpus_per_task), "--output=" + s.output};
  if (!s.partition.empty()) argv.push_back("--partition=" + s.partition);
  if (!s.time.empty()) argv.push_back("--time=" + s.time);
  argv.insert(argv.end(), s.extra_args.begin(), s.extra_args.end());
  argv.push_back(s.script);
  return argv;
}

namespace {

// Throws "sbatch refused the job: <its stderr on one line>" unless sbatch exited 0.
void throw_unless_accepted(const ProgramOutput& out, const std::string& job_name) {
  if (out.started && out.exit_code == 0) return;
  if (out.timed_out)
    throw std::runtime_error("sbatch " + out.err + " and was stopped (is the Slurm controller up? scontrol ping); " +
                             "it may have made a job all the same: squeue --me --name=" + job_name);
  // sbatch's own lines start "sbatch: error: "; stderr_one_line joins them and drops our prefix only.
  std::string message = stderr_one_line(out.err);
  for (std::size_t at; (at = message.find("sbatch: error: ")) != std::string::npos;) message.erase(at, 15);
  throw std::runtime_error("sbatch refused the job: " +
                           (message.empty() ? "exit code " + std::to_string(out.exit_code) : message));
}

}  // namespace

void check_submission(const ArraySubmission& submission) {
  ArraySubmission probe = submission;
  probe.tasks = 1;
  probe.max_parallel = 0;
  std::vector<std::string> argv = sbatch_argv(probe);
  argv.back() = "--wrap=true";  // instead of the script, which is not written yet
  argv.insert(argv.begin() + 1, "--test-only");
  throw_unless_accepted(run_program(argv, {}, kSlurmSubmitTimeout), submission.job_name);
}

std::string submit_array(const ArraySubmission& submission) {
  const ProgramOutput out = run_program(sbatch_argv(submission), {}, kSlurmSubmitTimeout);
  throw_unless_accepted(out, submission.job_name);
  // --parsable: "JOBID" or "JOBID;CLUSTER".
  std::string id = out.out.substr(0, out.out.find_first_of(";\n"));
  while (!id.empty() && (id.back() == '\r' || id.back() == ' ')) id.pop_back();
  if (id.empty() || id.find_first_not_of("0123456789") != std::string::npos)
    throw std::runtime_error("sbatch printed no job id: '" + stderr_one_line(out.out) + "'");
  return id;
}

QueueReading read_queue(const std::string& job_id) {
  // SLURM_BITSTR_LEN=0: the pending part of an array ("3-7,9%2") is printed whole, never cut at 64
  // characters.
  const ProgramOutput out = run_program(
      {"squeue", "--noheader", "--jobs=" + job_id, "--states=all", "--format=%K|%T"}, {"SLURM_BITSTR_LEN=0"},
      kSlurmQueryTimeout);
  QueueReading reading;
  if (out.started && out.exit_code == 0) {
    reading.ok = true;
    reading.tasks = parse_task_states(out.out);
  } else if (out.started && out.err.find("Invalid job id") != std::string::npos) {
    reading.ok = true;  // purged (older than MinJobAge): nothing of it is pending or running
  } else if (out.timed_out) {
    reading.error = "squeue " + out.err + " (is the Slurm controller up? scontrol ping)";
  } else {
    reading.error = "squeue: " + stderr_one_line(out.err.empty() ? out.out : out.err);
  }
  return reading;
}

std::string cancel_job(const std::string& job_id) {
  const ProgramOutput out = run_program({"scancel", job_id}, {}, kSlurmQueryTimeout);
  if (out.started && out.exit_code == 0) return "";
  if (out.timed_out) return "scancel " + job_id + " " + out.err;
  return "scancel " + job_id + ": " + stderr_one_line(out.err);
}

std::size_t max_array_size(std::size_t fallback) {
  const ProgramOutput out = run_program({"scontrol", "show", "config"}, {}, kSlurmQueryTimeout);
  if (!out.started || out.exit_code != 0) return fallback;
  const std::size_t key = out.out.find("MaxArraySize");
  if (key == std::string::npos) return fallback;
  const std::size_t eq = out.out.find('=', key);
  if (eq == std::string::npos) return fallback;
  try {
    const unsigned long value = std::stoul(out.out.substr(eq + 1));
    return value > 0 ? value : fallback;
  } catch (const std::exception&) {
    return fallback;
  }
}

}  // namespace signalsim
