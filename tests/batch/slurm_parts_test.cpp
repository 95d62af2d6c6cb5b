// The Slurm back-end's SUMO-free and Slurm-free parts: squeue's task lines, chunk sizes within
// MaxArraySize, the chunk list and row files read back as written, sbatch's command line, the error
// rows of lost runs, task.sh with an --out path that is hostile to a shell, a Slurm command that
// never answers. (The back-end against a real Slurm: slurm_test.sh.)
#include <gtest/gtest.h>

#include <filesystem>

#include "batch/run_outputs.hpp"
#include "batch/run_row_file.hpp"
#include "batch/slurm/program_output.hpp"
#include "batch/slurm/slurm_chunks.hpp"
#include "batch/slurm/slurm_commands.hpp"
#include "batch/slurm/slurm_queue.hpp"
#include "batch/slurm/slurm_wait.hpp"
#include "test_files.hpp"

namespace signalsim {
namespace {

TEST(SlurmQueue, ReadsRunningEndedAndCompressedPendingTasks) {
  const TaskStates states = parse_task_states("0|COMPLETED\n1|CANCELLED\n4|RUNNING\n5-7,9%2|PENDING\nN/A|PENDING\n\n");
  const TaskStates expected = {{0, "COMPLETED"}, {1, "CANCELLED"}, {4, "RUNNING"},
                               {5, "PENDING"},   {6, "PENDING"},   {7, "PENDING"}, {9, "PENDING"}};
  EXPECT_EQ(states, expected);
  EXPECT_EQ(describe_task_states(states), "4 tasks pending, 1 running");
  EXPECT_EQ(parse_task_states("[2-3]|PENDING\n").size(), 2u);
  EXPECT_TRUE(parse_task_states("7-3|PENDING\nx|RUNNING\n").empty());  // not index lists
}

TEST(SlurmQueue, OnlyKnownActiveStatesKeepTheWaitGoing) {
  for (const char* state : {"PENDING", "RUNNING", "COMPLETING", "CONFIGURING", "SUSPENDED", "REQUEUED"})
    EXPECT_TRUE(is_active_task_state(state)) << state;
  for (const char* state : {"COMPLETED", "CANCELLED", "FAILED", "TIMEOUT", "NODE_FAIL", "OUT_OF_MEMORY", "SOMETHING_NEW"})
    EXPECT_FALSE(is_active_task_state(state)) << state;
  EXPECT_EQ(describe_task_states({{0, "COMPLETED"}}), "no task pending or running");
  EXPECT_EQ(describe_task_states({{0, "RUNNING"}}), "1 task running");
}

TEST(SlurmChunks, ChunkSizeStaysWithinMaxArraySize) {
  std::string note;
  EXPECT_EQ(chunk_size(18, 4, 1, 1001, note), 4u);
  EXPECT_EQ(note, "");
  EXPECT_EQ(chunk_size(18, 0, 2, 1001, note), 20u);  // default: 10 per CPU of a task
  EXPECT_EQ(chunk_size(25000, 10, 1, 1001, note), 25u);
  EXPECT_NE(note.find("MaxArraySize of 1001"), std::string::npos) << note;
  std::vector<ChunkRun> runs(7);
  const auto chunks = make_chunks(runs, 3);
  ASSERT_EQ(chunks.size(), 3u);
  EXPECT_EQ(chunks[2].size(), 1u);
}

TEST(SlurmChunks, ChunkListAndJobRecordReadBackAsWritten) {
  test::TempDir dir;
  ChunkList list;
  list.directory = "/some/where";
  list.timeout = 60;
  list.isolate = true;
  ChunkRun run;
  run.spec.index = 3;
  run.spec.scenario = "data/a b.yaml";
  run.spec.name = "a";
  run.spec.values = {{"country", "de"}, {"ego.route", "[[in_S, out_W]]"}};
  run.spec.set = {"country=de", "ego.route=[[in_S, out_W]]"};
  run.run_dir = "runs/0003-a";
  list.chunks = {{run}, {}};
  write_chunk_list(dir.path(), list);
  const ChunkList back = read_chunk_list(dir.path());
  EXPECT_EQ(back.directory, list.directory);
  EXPECT_EQ(back.timeout, 60);
  EXPECT_TRUE(back.isolate);
  ASSERT_EQ(back.chunks.size(), 2u);
  ASSERT_EQ(back.chunks[0].size(), 1u);
  EXPECT_EQ(back.chunks[0][0].spec.values, run.spec.values);
  EXPECT_EQ(back.chunks[0][0].spec.set, run.spec.set);
  EXPECT_EQ(back.chunks[0][0].run_dir, run.run_dir);

  EXPECT_FALSE(read_job_record(dir.path()));
  write_job_record(dir.path(), {"42", 6});
  ASSERT_TRUE(read_job_record(dir.path()));
  EXPECT_EQ(read_job_record(dir.path())->id, "42");
  EXPECT_EQ(read_job_record(dir.path())->tasks, 6u);
  remove_job_record(dir.path());
  EXPECT_FALSE(read_job_record(dir.path()));
}

TEST(RunRowFile, ARowReadsBackWithTheSameCells) {
  test::TempDir dir;
  std::filesystem::create_directories(dir.path() + "/runs/0002-x");
  EXPECT_FALSE(read_row_file(dir.path(), "runs/0002-x"));
  ResultRow row{2, {{"scenario", "x"}, {"country", "jp"}, {"status", "error"}, {"error", "said \"no\", twice\nagain"},
                    {"wall_time", "0.25"}, {"run_dir", "runs/0002-x"}}};
  write_row_file(dir.path(), "runs/0002-x", row);
  const auto back = read_row_file(dir.path(), "runs/0002-x");
  ASSERT_TRUE(back);
  EXPECT_EQ(back->run, 2u);
  EXPECT_EQ(back->cells, row.cells);
}

TEST(SlurmCommands, SbatchGetsTheArrayThrottleAndTheUsersArgumentsBeforeTheScript) {
  ArraySubmission s;
  s.script = "/o/slurm/task.sh";
  s.job_name = "signalsim-o";
  s.tasks = 6;
  s.max_parallel = 2;
  s.cpus_per_task = 4;
  s.output = output_pattern("/o 100%/slurm/logs", "task-%A_%a.log");  // the user's '%' is no pattern
  s.partition = "short";
  s.time = "30";
  s.extra_args = {"--account=proj"};
  const std::vector<std::string> expected = {
      "sbatch", "--parsable", "--job-name=signalsim-o", "--array=0-5%2", "--cpus-per-task=4",
      "--output=/o 100%%/slurm/logs/task-%A_%a.log", "--partition=short", "--time=30", "--account=proj",
      "/o/slurm/task.sh"};
  EXPECT_EQ(sbatch_argv(s), expected);
  EXPECT_THROW(output_pattern("/o\\x/slurm/logs", "task-%A_%a.log"), std::runtime_error);
}

TEST(SlurmChunks, TaskScriptPassesAHostileOutPathThroughWhole) {
  test::TempDir dir;
  // A newline, a fake #SBATCH line, quotes, '%', '\\' and a command substitution in --out.
  const std::string out = dir.path() + "/a b%j\\\n#SBATCH --wrap=x\n$(touch pwned)'\"";
  std::filesystem::create_directories(slurm_dir(out));
  const std::string script = write_task_script(out, "/bin/echo");
  const ProgramOutput ran = run_program({"/bin/sh", script}, {"SLURM_ARRAY_TASK_ID=3"});
  ASSERT_TRUE(ran.started) << ran.err;
  EXPECT_EQ(ran.exit_code, 0) << ran.err;
  EXPECT_EQ(ran.out, "run-chunk " + out + " 3\n");
  EXPECT_FALSE(std::filesystem::exists("pwned"));
  const std::string text = read_text_file(script);
  // sbatch reads #SBATCH lines up to the first command: only the fixed comments come before it.
  const std::string exec_line = "\nexec '/bin/echo' run-chunk '";
  ASSERT_NE(text.find(exec_line), std::string::npos) << text;
  EXPECT_EQ(text.substr(0, text.find(exec_line)).find(dir.path()), std::string::npos) << text;
}

TEST(ProgramOutput, AProgramThatNeverAnswersIsStoppedAtTheTimeout) {
  const ProgramOutput hung = run_program({"sleep", "60"}, {}, 0.2);
  EXPECT_TRUE(hung.started);
  EXPECT_TRUE(hung.timed_out);
  EXPECT_NE(hung.exit_code, 0);
  EXPECT_EQ(hung.err, "did not answer within 0.2 s");
  const ProgramOutput quick = run_program({"sh", "-c", "echo hi"}, {}, 30);
  EXPECT_FALSE(quick.timed_out);
  EXPECT_EQ(quick.exit_code, 0);
  EXPECT_EQ(quick.out, "hi\n");
}

TEST(SlurmWait, ALostRunIsAnErrorRowNamedByItsTasksState) {
  test::TempDir dir;
  RunSpec run;
  run.index = 4;
  run.scenario = "s.yaml";
  run.name = "s";
  run.values = {{"country", "kr"}};
  const ResultRow timed_out = lost_run_row(run, dir.path(), "runs/0004-s", "42_1", "TIMEOUT");
  EXPECT_EQ(timed_out.cells.at("status"), "error");
  EXPECT_EQ(timed_out.cells.at("country"), "kr");
  EXPECT_FALSE(timed_out.cells.count("run_dir"));  // no such directory
  EXPECT_EQ(timed_out.cells.at("error").rfind("Slurm task 42_1 ended TIMEOUT before this run finished", 0), 0u);
  const ResultRow unknown = lost_run_row(run, dir.path(), "runs/0004-s", "42_5", "");
  EXPECT_NE(unknown.cells.at("error").find("Slurm no longer knows the task"), std::string::npos);
  const ResultRow completed = lost_run_row(run, dir.path(), "runs/0004-s", "42_5", "COMPLETED");
  EXPECT_NE(completed.cells.at("error").find("filesystem the nodes share"), std::string::npos);
}

}  // namespace
}  // namespace signalsim
