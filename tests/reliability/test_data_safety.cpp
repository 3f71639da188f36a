// Reliability: a user's files, a run's results and the machine are safe from
// whatever a user (or an attacker) types as an output path, from --force, from
// signals and from a full disk (issue 12, items 1-6). Each case failed before
// the fix it guards.
#include <doctest/doctest.h>
#include <signal.h>
#include <sys/mount.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support.hpp"

namespace fs = std::filesystem;

namespace {

// A quick valid scene.
const std::string kScene =
    "[model]\nenergy = 15.0\n[ensemble]\ntrajectories = 200\n[integrator]\nstep = 0.02\n"
    "[run]\naverage = 1.0\nduration = 2.0\n[observe]\nvelocity_map = { nside = 8 }\n"
    "energy_error = { every = 0.5 }\n[output]\nimages = false\n";

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::string write_scene(const std::string& dir, const std::string& text = kScene) {
  const std::string path = dir + "/scene.toml";
  std::ofstream(path) << text;
  return path;
}

std::vector<std::string> run_args(const std::string& scene, const std::string& out,
                                  std::vector<std::string> extra = {}) {
  std::vector<std::string> a = {"run", scene, "--quiet", "--device", "cpu", "--out", out};
  a.insert(a.end(), extra.begin(), extra.end());
  return a;
}

// Every path under `root` whose name contains `part` (or is `part`, if exact).
std::vector<std::string> find_named(const std::string& root, const std::string& part, bool exact = false) {
  std::vector<std::string> found;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(root, ec); !ec && it != fs::recursive_directory_iterator(); ++it) {
    const std::string name = it->path().filename().string();
    if (exact ? name == part : contains(name, part)) found.push_back(it->path().string());
  }
  return found;
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

nlohmann::json summary_of(const std::string& dir) { return nlohmann::json::parse(slurp(dir + "/summary.json")); }

// A pid that belonged to a process that has ended.
int dead_pid() {
  const pid_t p = fork();
  if (p == 0) _exit(0);
  int status;
  waitpid(p, &status, 0);
  return p;
}

const char* kFramesSets[] = {"--set", "observe.frames.times=[0,1,2]", "--set", "output.images=true"};

}  // namespace

TEST_SUITE("reliability") {
  TEST_CASE("1. a movie into directories named like shell commands runs no command") {
#ifndef ARNOLDWEB_HAVE_CAIRO
    // frames (and so the movie) are drawn with cairo
    // (the rest of the suite runs: this case alone reports itself skipped)
    MESSAGE("SKIPPED: this build has no cairo, so it writes no frames and no movie");
    return;
#endif
    // a stand-in ffmpeg on PATH records the arguments it is given and writes
    // the output file: with a shell in between, the names below would run
    // `touch INJECTED` before any ffmpeg is reached
    const std::string root = awtest::temp_dir("inject");
    const std::string bin = root + "/bin";
    fs::create_directories(bin);
    std::ofstream(bin + "/ffmpeg") << "#!/bin/sh\nprintf '%s\\n' \"$@\" > \"$FAKE_FFMPEG_ARGS\"\n"
                                      "for last; do :; done\n: > \"$last\"\n";
    fs::permissions(bin + "/ffmpeg", fs::perms::owner_all);
    const std::string scene = write_scene(root);
    for (const std::string name : {"a'; touch INJECTED; 'b", "a\"; touch INJECTED; \"b", "a$(touch INJECTED)b",
                                   "a`touch INJECTED`b", "a; touch INJECTED"}) {
      CAPTURE(name);
      const std::string work = awtest::temp_dir("inject-run");
      awtest::CliOptions o;
      o.cwd = work;
      o.env = {"PATH=" + bin + ":/usr/bin:/bin", "FAKE_FFMPEG_ARGS=" + work + "/args.txt"};
      std::string out;
      auto args = run_args(scene, name, {kFramesSets, kFramesSets + 4});
      CHECK(awtest::run_cli(args, &out, o) == 0);
      CAPTURE(out);
      CHECK(find_named(work, "INJECTED", true).empty());
      CHECK(fs::exists(work + "/" + name + "/frames.mp4"));
      const std::string recorded = slurp(work + "/args.txt");
      CHECK(contains(recorded, name + ".partial-"));  // the name arrived as one argument, intact
      CHECK(contains(recorded, "/frames/frame_%03d.png\n"));
    }
  }

  TEST_CASE("2. --force replaces only a directory that arnoldweb wrote") {
    const std::string root = awtest::temp_dir("force");
    const std::string scene = write_scene(root);
    std::string out;
    // the current directory (which holds the scene)
    awtest::CliOptions here;
    here.cwd = root;
    CHECK(awtest::run_cli(run_args("scene.toml", ".", {"--force"}), &out, here) == 2);
    CHECK(contains(out, "refusing to replace it"));
    CHECK(fs::exists(scene));
    // the directory holding the scene file, and its parent
    CHECK(awtest::run_cli(run_args(scene, root, {"--force"}), &out) == 2);
    CHECK(fs::exists(scene));
    CHECK(awtest::run_cli(run_args(scene, fs::path(root).parent_path().string(), {"--force"}), &out) == 2);
    CHECK(fs::exists(scene));
    // / and $HOME, even when $HOME looks like an output directory of ours
    CHECK(awtest::run_cli(run_args(scene, "/", {"--force"}), &out) == 2);
    const std::string home = awtest::temp_dir("force-home") + "/home";
    REQUIRE(awtest::run_cli(run_args(scene, home), &out) == 0);
    awtest::CliOptions with_home;
    with_home.env = {"HOME=" + home};
    CHECK(awtest::run_cli(run_args(scene, home, {"--force"}), &out, with_home) == 2);
    CHECK(contains(out, "home directory"));
    CHECK(fs::exists(home + "/summary.json"));
    // an earlier run's directory is replaced ...
    const std::string earlier = awtest::temp_dir("force-ours") + "/out";
    REQUIRE(awtest::run_cli(run_args(scene, earlier), &out) == 0);
    const std::string date_before = summary_of(earlier)["date"];
    CHECK(awtest::run_cli(run_args(scene, earlier, {"--force", "--set", "ensemble.seed=2"}), &out) == 0);
    CHECK(summary_of(earlier)["scene"]["ensemble"]["seed"] == 2);
    // ... but not once the user has put something of their own into it
    std::ofstream(earlier + "/notes.txt") << "mine";
    fs::create_directories(earlier + "/plots");
    CHECK(awtest::run_cli(run_args(scene, earlier, {"--force"}), &out) == 2);
    CHECK(contains(out, "notes.txt"));
    CHECK(slurp(earlier + "/notes.txt") == "mine");
    CHECK(summary_of(earlier)["scene"]["ensemble"]["seed"] == 2);
    // a symbolic link to an output directory is not followed
    const std::string link = awtest::temp_dir("force-link") + "/link";
    const std::string target = awtest::temp_dir("force-link") + "/target";
    REQUIRE(awtest::run_cli(run_args(scene, target), &out) == 0);
    fs::create_directory_symlink(target, link);
    CHECK(awtest::run_cli(run_args(scene, link, {"--force"}), &out) == 2);
    CHECK(contains(out, "symbolic link"));
    CHECK(fs::exists(target + "/summary.json"));
    (void)date_before;
  }

  TEST_CASE("3. counts derived from the scene's numbers cannot overflow") {
    const std::string root = awtest::temp_dir("overflow");
    const std::string scene = write_scene(root);
    std::string out;
    CHECK(awtest::run_cli(run_args(scene, root + "/a", {"--set", "run.duration=2e19", "--set", "run.average=1e19"}),
                          &out) == 2);
    CHECK(contains(out, "run.duration"));
    CHECK(contains(out, "at most 1e+15"));
    CHECK(contains(out, "the largest run.duration with this step is 2e+13 T"));
    CHECK(awtest::run_cli(run_args(scene, root + "/b", {"--set", "integrator.step=1e-300"}), &out) == 2);
    CHECK(contains(out, "integrator.step"));
    CHECK(contains(out, "smallest integrator.step"));
    CHECK_FALSE(fs::exists(root + "/a"));
    CHECK_FALSE(fs::exists(root + "/b"));
  }

  TEST_CASE("4. a full disk: exit 3 with the bytes needed, the old directory untouched, what was written kept") {
    const std::string root = awtest::temp_dir("full");
    const std::string scene = write_scene(root);
    const std::string out_dir = root + "/out";
    std::string out;
    REQUIRE(awtest::run_cli(run_args(scene, out_dir), &out) == 0);
    const std::string before = slurp(out_dir + "/summary.json");
    // states of 5000 trajectories need ~700 kB: more than this "disk" takes
    awtest::CliOptions small_disk;
    small_disk.file_size_limit = 100 * 1000;
    const int rc = awtest::run_cli(
        run_args(scene, out_dir,
                 {"--force", "--set", "ensemble.trajectories=5000", "--set", "observe.final_states=true"}),
        &out, small_disk);
    CAPTURE(out);
    CHECK(rc == 3);
    CHECK(contains(out, "states.h5"));
    CHECK(contains(out, "to write"));
    CHECK(contains(out, "left as it was"));
    CHECK(slurp(out_dir + "/summary.json") == before);
    const auto kept = find_named(root, "out.incomplete-");
    REQUIRE(kept.size() == 1);
    CHECK(contains(out, kept[0]));
    CHECK(fs::exists(kept[0] + "/map.h5"));
    CHECK_FALSE(fs::exists(kept[0] + "/states.h5"));
    CHECK(find_named(root, ".tmp-").empty());
    CHECK(find_named(root, ".partial-").empty());
  }

  TEST_CASE("5. SIGINT, SIGTERM and SIGHUP stop after the current chunk and keep what was computed") {
    const std::string root = awtest::temp_dir("signals");
    const std::string scene = write_scene(root);
    for (const int sig : {SIGTERM, SIGHUP, SIGINT}) {
      CAPTURE(sig);
      for (const bool twice : {false, true}) {
        CAPTURE(twice);
        const std::string out_dir = root + "/out-" + std::to_string(sig) + (twice ? "-2" : "");
        auto args = run_args(scene, out_dir, {"--set", "ensemble.trajectories=20000000", "--set", "ensemble.chunk=2000"});
        args.erase(args.begin() + 2);  // not --quiet: wait for the progress line
        awtest::StartedCli cli = awtest::start_cli(args);
        REQUIRE(cli.wait_for("progress:", 60));
        kill(cli.pid, sig);
        if (twice) kill(cli.pid, sig);  // held while the outputs are written
        const int rc = cli.finish();
        CAPTURE(cli.output);
        CHECK(rc == 128 + sig);
        CHECK(contains(cli.output, "stopped by SIG"));
        REQUIRE(fs::exists(out_dir + "/summary.json"));
        const auto j = summary_of(out_dir);
        CHECK(j["interrupted"] == true);
        CHECK(j["completed"].get<std::uint64_t>() < 20000000u);
        CHECK(j["completed"].get<std::uint64_t>() % 2000 == 0);
        CHECK(j["binned"].get<std::uint64_t>() + j["flagged"]["total"].get<std::uint64_t>() +
                  j["left_region"].get<std::uint64_t>() ==
              j["completed"].get<std::uint64_t>());
        CHECK(fs::exists(out_dir + "/map.h5"));
        CHECK(find_named(root, ".partial-").empty());
      }
    }
  }

  TEST_CASE("5. staging directories of dead processes are removed, and only those") {
    const std::string root = awtest::temp_dir("stale");
    const std::string scene = write_scene(root);
    const std::string out_dir = root + "/out";
    const std::string stale = out_dir + ".partial-" + std::to_string(dead_pid());
    fs::create_directories(stale);
    std::ofstream(stale + "/.arnoldweb-staging") << "arnoldweb staging directory\n";
    std::ofstream(stale + "/map.h5") << "half";
    const std::string lookalike = out_dir + ".partial-" + std::to_string(dead_pid() + 1000000);
    fs::create_directories(lookalike);
    std::ofstream(lookalike + "/mine.txt") << "mine";
    std::string out;
    CHECK(awtest::run_cli(run_args(scene, out_dir), &out) == 0);
    CHECK_FALSE(fs::exists(stale));
    CHECK(fs::exists(lookalike + "/mine.txt"));  // no marker: not ours
  }

  TEST_CASE("6. output paths are normalised and checked before anything is computed") {
    const std::string root = awtest::temp_dir("paths");
    const std::string scene = write_scene(root);
    std::string out;
    // a trailing slash
    CHECK(awtest::run_cli(run_args(scene, root + "/res/"), &out) == 0);
    CHECK(fs::exists(root + "/res/summary.json"));
    CHECK(find_named(root, ".partial-").empty());
    CHECK(awtest::run_cli(run_args(scene, root + "/res//", {"--force"}), &out) == 0);
    // an empty name is refused, not ignored
    CHECK(awtest::run_cli(run_args(scene, ""), &out) == 2);
    CHECK(contains(out, "empty"));
    // places that cannot be written are refused before computing: 10^12
    // trajectories would take days
    const std::vector<std::string> huge = {"--set", "ensemble.trajectories=1000000000000"};
    CHECK(awtest::run_cli(run_args(scene, "/proc/arnoldweb-out", huge), &out) == 3);
    CHECK(contains(out, "/proc/arnoldweb-out"));
    CHECK(awtest::run_cli(run_args(scene, root + "/" + std::string(300, 'x'), huge), &out) == 3);
    CHECK(contains(out, "File name too long"));
    // `check` refuses them just the same
    CHECK(awtest::run_cli({"check", scene, "--out", "/proc/arnoldweb-out"}, &out) == 3);
    CHECK(awtest::run_cli({"check", scene, "--out", ""}, &out) == 2);
    // a name that is not UTF-8 is refused: the scene (TOML, in summary.json) could not record it, and
    // recorded as U+FFFD it would name another directory
    const std::string odd = root + "/odd-\xff\xfe-name";
    CHECK(awtest::run_cli(run_args(scene, odd), &out) == 2);
    CHECK(contains(out, "odd-\\xff\\xfe-name: output.dir: is not UTF-8 text"));
    CHECK_FALSE(fs::exists(odd));
  }

  TEST_CASE("issue 37, 8. --force deletes only files whose digest summary.json records, and still matches") {
    const std::string root = awtest::temp_dir("force-digests");
    const std::string scene = write_scene(root);
    std::string out;
    const std::string dir = root + "/out";
    REQUIRE(awtest::run_cli(run_args(scene, dir), &out) == 0);
    const std::string summary = slurp(dir + "/summary.json");
    // a summary.json (copied from elsewhere) that lists the user's thesis.tex in "files", with no digest:
    // deleted by --force before
    nlohmann::json j = nlohmann::json::parse(summary);
    j["files"].push_back("thesis.tex");
    std::ofstream(dir + "/summary.json") << j.dump(2);
    std::ofstream(dir + "/thesis.tex") << "\\chapter{Mine}";
    CHECK(awtest::run_cli(run_args(scene, dir, {"--force"}), &out) == 2);
    CAPTURE(out);
    CHECK(contains(out, "it holds files that arnoldweb did not write (thesis.tex)"));
    CHECK(slurp(dir + "/thesis.tex") == "\\chapter{Mine}");
    fs::remove(dir + "/thesis.tex");
    // an output changed since the run wrote it is no longer the run's
    std::ofstream(dir + "/summary.json") << summary;
    std::ofstream(dir + "/map.h5", std::ios::app | std::ios::binary) << "edited";
    const std::string edited = slurp(dir + "/map.h5");
    CHECK(awtest::run_cli(run_args(scene, dir, {"--force"}), &out) == 2);
    CHECK(contains(out, "map.h5 (changed since the run wrote it)"));
    CHECK(slurp(dir + "/map.h5") == edited);
    // a directory whose summary.json records no digests (before 2026-11-26): nothing tells its files
    // from a user's, so it is refused rather than guessed at
    j = nlohmann::json::parse(summary);
    j.erase("file_digests");
    std::ofstream(dir + "/summary.json") << j.dump(2);
    CHECK(awtest::run_cli(run_args(scene, dir, {"--force"}), &out) == 2);
    CHECK(contains(out, "records no file digests"));
    CHECK(slurp(dir + "/map.h5") == edited);
    // the run's own, unchanged, is replaced
    const std::string mine = root + "/mine";
    REQUIRE(awtest::run_cli(run_args(scene, mine), &out) == 0);
    CHECK(awtest::run_cli(run_args(scene, mine, {"--force", "--set", "ensemble.seed=7"}), &out) == 0);
    CHECK(summary_of(mine)["scene"]["ensemble"]["seed"] == 7);
  }
}

// With the real ffmpeg (CI installs it): the movie is made and nothing runs.
TEST_SUITE("reliability-ffmpeg") {
  TEST_CASE("1. frames and a movie into directories named like shell commands, with ffmpeg") {
    if (!awtest::require(fs::exists("/usr/bin/ffmpeg"), "reliability-ffmpeg",
                         "ffmpeg is not installed (/usr/bin/ffmpeg); Debian: apt-get install ffmpeg"))
      return;
    const std::string root = awtest::temp_dir("inject-ffmpeg");
    const std::string scene = write_scene(root);
    for (const std::string name : {"a'; touch INJECTED; 'b", "a\"; touch INJECTED; \"b"}) {
      CAPTURE(name);
      awtest::CliOptions o;
      o.cwd = awtest::temp_dir("inject-ffmpeg-run");
      std::string out;
      CHECK(awtest::run_cli(run_args(scene, name, {kFramesSets, kFramesSets + 4}), &out, o) == 0);
      CAPTURE(out);
      CHECK(find_named(o.cwd, "INJECTED", true).empty());
      CHECK(fs::file_size(o.cwd + "/" + name + "/frames.mp4") > 1000);
      CHECK(fs::exists(o.cwd + "/" + name + "/frames/frame_001.png"));
    }
  }
}

// On a small file system (a tmpfs, where this process may mount one).
TEST_SUITE("reliability-tmpfs") {
  TEST_CASE("4. too little free space is refused before computing, the old directory untouched") {
    const std::string root = awtest::temp_dir("tmpfs");
    const std::string disk = root + "/disk";
    fs::create_directories(disk);
    const bool mounted = ::mount("tmpfs", disk.c_str(), "tmpfs", 0, "size=400k") == 0;
    if (!awtest::require(mounted, "reliability-tmpfs",
                         std::string("cannot mount a tmpfs here (") + std::strerror(errno) + "; needs root)"))
      return;
    struct Unmount {
      std::string path;
      ~Unmount() { ::umount(path.c_str()); }
    } unmount{disk};
    const std::string scene = write_scene(root);
    std::string out;
    REQUIRE(awtest::run_cli(run_args(scene, disk + "/out"), &out) == 0);
    const std::string before = slurp(disk + "/out/summary.json");
    CHECK(awtest::run_cli(run_args(scene, disk + "/out", {"--force", "--set", "ensemble.trajectories=50000", "--set",
                                                           "observe.final_states=true"}),
                          &out) == 3);
    CAPTURE(out);
    CHECK(contains(out, "free"));
    CHECK(contains(out, "nothing was computed"));
    CHECK(slurp(disk + "/out/summary.json") == before);
    CHECK(find_named(disk, ".partial-").empty());
  }
}
