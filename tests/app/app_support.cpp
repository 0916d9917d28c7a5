#include "app_support.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"

namespace eco::test {

CommandResult ecoforest(const std::string& arguments) {
  return runCommand(std::string(ECOFOREST_EXE) + " " + arguments);
}

const std::filesystem::path& shortDefaultRun() {
  static const std::filesystem::path dir = [] {
    auto d = freshDirectory("app_short_run");
    CommandResult r = ecoforest("run --years 20 --out " + d.string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return d;
  }();
  return dir;
}

std::optional<ConfinedResult> inSmallFileSystem(const std::string& commandLine, int kilobytes,
                                                const std::string& mountOptions) {
  static const bool possible =
      runCommand("unshare -rm sh -c 'mount -t tmpfs tmpfs /tmp' 2>&1").exitCode == 0;
  if (!possible) return std::nullopt;
  const std::filesystem::path space = freshDirectory("small_fs");
  constexpr int kCannotMount = 99;
  const std::string script =
      "mount -t tmpfs -o size=" + std::to_string(kilobytes) + "k" +
      (mountOptions.empty() ? "" : "," + mountOptions) + " tmpfs " + space.string() + " || exit " +
      std::to_string(kCannotMount) + "\nexport SPACE=" + space.string() + "\n(" + commandLine +
      ")\nrc=$?\necho '--- files'\n(cd \"$SPACE\" && find . -mindepth 1 | sort)\n" + "exit $rc\n";
  const std::filesystem::path scriptFile =
      space.parent_path() / (space.filename().string() + ".sh");
  writeFile(scriptFile, script);
  CommandResult r = runCommand("unshare -rm sh " + scriptFile.string());
  std::filesystem::remove(scriptFile);  // beside the folder: the tmpfs covered the folder
  if (r.exitCode == kCannotMount) return std::nullopt;
  ConfinedResult confined;
  const std::size_t marker = r.output.rfind("--- files\n");
  if (marker != std::string::npos) {
    confined.files = r.output.substr(marker + 10);
    r.output.resize(marker);
  }
  confined.result = r;
  return confined;
}

void expectFullAndReadOnlyDisksFailCleanly(const std::string& arguments, int kilobytes,
                                           const std::string& fullDiskMessage) {
  struct Disk {
    int kilobytes;
    const char* mountOptions;
    std::string message;
  };
  for (const Disk& disk :
       {Disk{kilobytes, "", fullDiskMessage}, Disk{1000, "ro", "Read-only file system"}}) {
    const auto confined = inSmallFileSystem(std::string(ECOFOREST_EXE) + " " + arguments,
                                            disk.kilobytes, disk.mountOptions);
    if (!confined) GTEST_SKIP() << "cannot mount a tmpfs in a user namespace here (unshare -rm)";
    EXPECT_EQ(confined->result.exitCode, kExitEnvironment) << arguments << "\n"
                                                           << confined->result.output;
    EXPECT_NE(confined->result.output.find(disk.message), std::string::npos)
        << arguments << "\n"
        << confined->result.output;
    EXPECT_EQ(confined->files, "") << arguments;
  }
}

CommandResult interruptWhen(const std::string& arguments, const std::string& condition) {
  return runCommand("(" + std::string(ECOFOREST_EXE) + " " + arguments + " & pid=$!\nuntil " +
                    condition + " || ! kill -0 $pid 2>/dev/null; do sleep 0.02; done\n" +
                    "kill -INT $pid 2>/dev/null; wait $pid)");
}

bool holdsATemporary(const std::string& files) {
  return files.find(".tmp-") != std::string::npos || files.find(".partial") != std::string::npos;
}

}  // namespace eco::test
