// Shared helpers of the command-line tests that need a run folder.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "test_files.hpp"

namespace eco::test {

// Runs the ecoforest program with these arguments.
CommandResult ecoforest(const std::string& arguments);
// A 20-year run of the default scenario (snapshots of years 10 and 20), made once per test
// process.
const std::filesystem::path& shortDefaultRun();

// A command line run with $SPACE a fresh tmpfs of `kilobytes` in a private mount namespace
// (unshare): a full disk, or with mountOptions "ro" a read-only folder, without touching the
// machine's file systems. The command runs in a subshell, so it may end with `exit`.
struct ConfinedResult {
  CommandResult result;
  std::string files;  // what is in $SPACE afterwards: relative paths, one a line, sorted
};
// Nothing where this machine cannot make one (no user namespaces): the test then skips.
std::optional<ConfinedResult> inSmallFileSystem(const std::string& commandLine, int kilobytes,
                                                const std::string& mountOptions = "");
#define ECO_SKIP_WITHOUT(confined)                                                    \
  if (!(confined))                                                                    \
  GTEST_SKIP() << "cannot mount a tmpfs in a user namespace here (unshare -rm): the " \
                  "full-disk and read-only tests need one"

// Runs ecoforest with these arguments (which name their output under $SPACE) twice: on a
// tmpfs of `kilobytes` (a full disk) and on a read-only one. Expects each time a failure of
// the environment (exit 3) whose message holds `fullDiskMessage`, or "Read-only file
// system", and nothing at all left in $SPACE. Skips where no tmpfs can be made.
void expectFullAndReadOnlyDisksFailCleanly(const std::string& arguments, int kilobytes,
                                           const std::string& fullDiskMessage);

// Starts ecoforest with these arguments, waits until the shell test `condition` holds (e.g.
// [ -e FILE ], checked every 20 ms), then sends Ctrl-C (SIGINT) and returns how it ended.
CommandResult interruptWhen(const std::string& arguments, const std::string& condition);

// Whether a listing of files holds a temporary of an interrupted write (AtomicFile's
// NAME.tmp-PID-N, the frame sinks' .partial).
bool holdsATemporary(const std::string& files);

}  // namespace eco::test
