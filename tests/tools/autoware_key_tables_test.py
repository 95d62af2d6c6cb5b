#!/usr/bin/env python3
"""tools/autoware_key_tables on a fixture (data/fixture.yaml: two small repositories in the shape of
autoware_launch and autoware_universe, made into git repositories here with fixed names and dates):
the table it writes is data/autoware_keys.expected.yaml to the byte (known keys in file order, a key
the module dropped while autoware_launch still ships it, a drop across a renamed file, a key only
autoware_launch has); --write-files writes a file's keys, nesting and values; --check passes on the
table and names the first differing line of another; a missing commit is one line and exit 2.

usage: autoware_key_tables_test.py SOURCE_DIR   (exit 77, skipped, without git or python3-yaml)
"""
import difflib
import os
import shutil
import subprocess
import sys
import tempfile

try:
    import yaml
except ImportError:
    sys.exit(77)

SOURCE = sys.argv[1]
HERE = os.path.join(SOURCE, "tests", "tools", "data")
TOOL = os.path.join(SOURCE, "tools", "autoware_key_tables")
FAILURES = []


def git(repo, *args, date=None):
    env = dict(os.environ, GIT_CONFIG_GLOBAL=os.devnull, GIT_CONFIG_NOSYSTEM="1",
               GIT_AUTHOR_NAME="fixture", GIT_AUTHOR_EMAIL="fixture@example.org",
               GIT_COMMITTER_NAME="fixture", GIT_COMMITTER_EMAIL="fixture@example.org")
    if date:
        env.update(GIT_AUTHOR_DATE=date, GIT_COMMITTER_DATE=date)
    subprocess.run(["git", "-C", repo, *args], env=env, check=True, capture_output=True)


def make_repository(path, commits):
    os.makedirs(path)
    git(path, "init", "-q", "-b", "main")
    for commit in commits:
        for old, new in (commit.get("rename") or {}).items():
            os.makedirs(os.path.dirname(os.path.join(path, new)), exist_ok=True)
            git(path, "mv", old, new)
        for name, text in (commit.get("files") or {}).items():
            os.makedirs(os.path.dirname(os.path.join(path, name)), exist_ok=True)
            with open(os.path.join(path, name), "w", encoding="utf-8") as out:
                out.write(text)
        git(path, "add", "-A")
        git(path, "commit", "-q", "-m", commit["message"], date=commit["date"])
    return os.path.join(path, ".git")


def run_tool(*args):
    return subprocess.run([sys.executable, TOOL, *args], capture_output=True, text=True)


def expect(good, what):
    print(("ok   " if good else "FAIL ") + what)
    if not good:
        FAILURES.append(what)


def same_text(actual, expected_file, what):
    with open(expected_file, encoding="utf-8") as f:
        expected = f.read()
    if actual != expected:
        sys.stdout.writelines(difflib.unified_diff(expected.splitlines(True), actual.splitlines(True),
                                                   expected_file, "written"))
    expect(actual == expected, what)


def main():
    if shutil.which("git") is None:
        return 77
    with open(os.path.join(HERE, "fixture.yaml"), encoding="utf-8") as f:
        fixture = yaml.safe_load(f)
    work = tempfile.mkdtemp(prefix="autoware-key-tables-")
    try:
        launch = make_repository(os.path.join(work, "launch"), fixture["autoware_launch"])
        universe = make_repository(os.path.join(work, "universe"), fixture["autoware_universe"])
        sources = ["--launch", launch, "main", "--universe", universe, "main",
                   "--launch-name", "fixture/autoware_launch", "--universe-name", "fixture/autoware_universe"]
        expected_table = os.path.join(HERE, "autoware_keys.expected.yaml")
        files = os.path.join(work, "files")
        done = run_tool(*sources, "--write-files", files)
        expect(done.returncode == 0 and done.stderr == "", f"the tool ran: exit {done.returncode} {done.stderr.strip()}")
        same_text(done.stdout, expected_table, "the table is autoware_keys.expected.yaml")
        with open(os.path.join(files, "traffic_light.param.yaml"), encoding="utf-8") as f:
            same_text(f.read(), os.path.join(HERE, "traffic_light.expected.param.yaml"),
                      "--write-files: traffic_light.param.yaml with its keys, nesting and values")
        expect(sorted(os.listdir(files)) == sorted([
            "behavior_path_planner.param.yaml", "traffic_light.param.yaml", "behavior_velocity_planner_common.param.yaml",
            "lane_change.param.yaml", "static_obstacle_avoidance.param.yaml", "start_planner.param.yaml",
            "goal_planner.param.yaml", "vehicle_info.param.yaml"]), "--write-files: the eight files")

        done = run_tool(*sources, "--check", expected_table)
        expect(done.returncode == 0 and done.stdout == "", f"--check passes on the table: {done.stdout.strip()}")
        stale = os.path.join(work, "stale.yaml")
        with open(expected_table, encoding="utf-8") as f:
            text = f.read()
        with open(stale, "w", encoding="utf-8") as f:
            f.write(text.replace("      - allow_area\n", ""))
        done = run_tool(*sources, "--check", stale)
        line = text.splitlines().index("      - allow_area") + 1
        expect(done.returncode == 1 and done.stdout.startswith(f"{stale}:{line}: not what the repositories give"),
               f"--check names the first differing line: {done.stdout.strip()}")

        done = run_tool("--launch", launch, "no-such-commit", "--universe", universe, "main")
        expect(done.returncode == 2 and done.stderr == f"autoware_key_tables: {launch}: no commit no-such-commit\n",
               f"a missing commit is one line, exit 2: {done.returncode} {done.stderr.strip()}")
    finally:
        shutil.rmtree(work, ignore_errors=True)
    print("autoware_key_tables: " + ("all checks passed" if not FAILURES else f"{len(FAILURES)} failure(s)"))
    return 1 if FAILURES else 0


if __name__ == "__main__":
    sys.exit(main())
