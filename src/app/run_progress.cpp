#include "app/run_progress.hpp"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <string>

#include <fmt/format.h>

#include "core/progress.hpp"

namespace eco {
namespace {

std::string clock(double seconds) {
  const int s = static_cast<int>(seconds + 0.5);
  return s >= 3600 ? fmt::format("{}:{:02d}:{:02d}", s / 3600, s / 60 % 60, s % 60)
                   : fmt::format("{}:{:02d}", s / 60, s % 60);
}

// Years a second, or seconds a year where a year takes longer than a second (a landscape's
// years take half a minute: "0.0 years/s" would say nothing).
std::string pace(double yearsPerSecond) {
  if (yearsPerSecond >= 1.0 || yearsPerSecond <= 0.0)
    return fmt::format("{:.1f} years/s", yearsPerSecond);
  return fmt::format("{:.1f} s/year", 1.0 / yearsPerSecond);
}

}  // namespace

void reportToTheUser(RunOptions& options) {
  const bool terminal = Progress::stderrIsTerminal();
  options.progress = [terminal](const RunProgress& p) { showRunProgress(p, terminal); };
  options.warn = [](const std::string& message) {
    std::cerr << "ecoforest: warning: " << message << "\n";
  };
}

void showRunProgress(const RunProgress& p, bool terminal) {
  const int done = p.year - p.firstYear + 1;
  const double rate = p.seconds > 0.0 ? done / p.seconds : 0.0;
  const double eta = rate > 0.0 ? (p.lastYear - p.year) / rate : 0.0;
  if (terminal) {
    constexpr int kWidth = 24;
    const int filled = kWidth * p.year / p.lastYear;
    std::fprintf(stderr, "\ryear %d/%d [%s%s] %zu plants  %s  ETA %s   ", p.year, p.lastYear,
                 std::string(filled, '#').c_str(), std::string(kWidth - filled, '.').c_str(),
                 p.plants, pace(rate).c_str(), clock(eta).c_str());
    if (p.year == p.lastYear) std::fputc('\n', stderr);
    std::fflush(stderr);
    return;
  }
  const int every = std::max(1, (p.lastYear - p.firstYear + 1) / 10);
  if (done % every == 0 || p.year == p.lastYear)
    std::fprintf(stderr, "year %d/%d: %zu plants, %s, ETA %s\n", p.year, p.lastYear, p.plants,
                 pace(rate).c_str(), clock(eta).c_str());
}

}  // namespace eco
