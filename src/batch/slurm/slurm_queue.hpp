// What Slurm says about the array tasks of one job, from squeue's "%K|%T" lines (index or index
// range, state): which tasks are still pending or running, which ended and how, and the words the
// progress line shows ("Slurm job 42: 3 tasks pending, 2 running"). Without slurmdbd, sacct does not
// work, so squeue (--states=all, which keeps ended tasks for the cluster's MinJobAge) is the only
// source; a task cancelled while pending leaves no trace at all, so it is simply not in the map.
#pragma once

#include <cstddef>
#include <map>
#include <string>

namespace signalsim {

/// Array task index -> its state word (PENDING, RUNNING, COMPLETED, CANCELLED, TIMEOUT, ...).
using TaskStates = std::map<std::size_t, std::string>;

/// Parses squeue --noheader --format=%K|%T output. A pending part of an array comes as one line
/// with a range ("3-7,9%2"); lines it cannot read (a job without array, "N/A") are skipped.
TaskStates parse_task_states(const std::string& squeue_output);

/// True for a state in which the task may still write results (pending, running, completing,
/// suspended, requeued, ...). Every other state word is an end: an unknown one too, so that a state
/// word of a newer Slurm can never make signalsim wait forever.
bool is_active_task_state(const std::string& state);

/// "3 tasks pending, 2 running" (only the parts that are not zero; "no task pending or running").
std::string describe_task_states(const TaskStates& states);

}  // namespace signalsim
