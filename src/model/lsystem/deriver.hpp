// Derivation of RL-systems (Lluch et al., section 3, "Flow of execution"): every step
// rewrites each module of the string in parallel by the first production (in file order)
// whose strict predecessor, contexts and condition match; a module no production matches
// derives itself. Random variables draw one deviate per variable for matching and a fresh
// deviate per occurrence in the chosen successor. Control modules (Switch, Pendulum,
// Repetition, Prune) steer the derivation; after each step the turtle fills interrogation
// modules and prunes against the declared volume.
//
// Deviates are keyed by (seed, step, module index, variable, occurrence), so the result is
// the same on any number of threads.
#pragma once

#include <cstdint>
#include <optional>

#include "model/lsystem/lsystem.hpp"

namespace eco {

struct DeriveOptions {
  std::optional<int> iterations;          // MaxIt; unset: the file's ITERATIONS
  std::uint64_t seed = 1;                 // the individual
  std::optional<std::size_t> maxModules;  // unset: the file's MAXMODULES
};

struct DeriveStats {
  int steps = 0;
  std::size_t modulesRewritten = 0;  // input modules over all steps
  std::size_t modulesProduced = 0;   // output modules over all steps
};

// The axiom with its expressions evaluated (random variables drawn for step 0).
ModuleString instantiateAxiom(const LSystem& system, std::uint64_t seed, int maxIt);

// One derivation step: `numIt` counts from 1 (Green's NumIt), `maxIt` is MaxIt.
// Throws InputError naming the production that made most modules when the result would
// exceed `maxModules`.
void deriveStep(const LSystem& system, const ModuleString& in, ModuleString& out, int numIt,
                int maxIt, std::uint64_t seed, std::size_t maxModules);

// The axiom derived `iterations` times, with Prune cuts, interrogation and the pruning
// volume applied after every step.
ModuleString derive(const LSystem& system, const DeriveOptions& options,
                    DeriveStats* stats = nullptr);

// Removes every Prune module (%) together with the rest of its branch, up to the ']' that
// closes the branch (or the end of the string). Returns whether anything was removed.
bool applyPruneModules(ModuleString& string);

}  // namespace eco
