// A tree species as EcoMod describes it (Zamuda et al., section II): global (scalar)
// parameters, local parameters as polylines over Gravelius order g and Weibull order w, and
// the few things ecoforest adds (individual variation, colours). Loaded from TOML files in
// scenarios/species/; every default lives in species.cpp, where the file is read. The
// file's [ecology] table is the simulation's (sim/species_ecology.hpp): the model knows only
// trees.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include <glm/vec3.hpp>

#include "core/polyline.hpp"

namespace eco {

enum class LeafDistribution { Spiral, Stacked, Staggered, Bunched, Coniferous };
const char* toString(LeafDistribution distribution);
// The distribution of that name in the species file ("spiral", ...), if there is one.
std::optional<LeafDistribution> leafDistributionNamed(std::string_view name);
inline constexpr LeafDistribution kLeafDistributions[] = {
    LeafDistribution::Spiral, LeafDistribution::Stacked, LeafDistribution::Staggered,
    LeafDistribution::Bunched, LeafDistribution::Coniferous};

// What a leaf card shows; the coniferous distribution always uses single needles.
enum class LeafShape { Broadleaf, NeedleTuft };
const char* toString(LeafShape shape);  // as in the species file

// The auxiliary graphs of eqs. (1)-(6), each a polyline over g or over w.
struct LocalGraphs {
  Polyline ksG, ksW;          // strand distribution k_s^g in [1/2, 1], k_s^w in [0, 2]
  Polyline alphaG, alphaW;    // branching angle alpha^g in degrees, alpha^w in [0, 2]
  Polyline alphaMG, alphaMW;  // gravimorphism alpha_m^g in degrees, alpha_m^w in [0, 2]
  Polyline maxLenG, maxLenW;  // maximum relative length M^g in [0, 10], M^w in [0, 2]
  Polyline klG, klW;          // length scaling k_l^g in [0, 10], k_l^w in [0, 2]
  Polyline minLenG, minLenW;  // minimum relative length m^g in [0, 10], m^w in [0, 2]
};

// EcoMod's global parameters with the paper's symbols.
struct StrandParams {
  int strands = 1000;             // S, total strands (= terminal segments)
  double trunkLength_m = 5.0;     // l_0^{0,0} (the paper's L_0), length of the base trunk
  double kd = 0.01;               // thickness coefficient: diameter d = k_d sqrt(S_0), m
  double phyllotaxis_deg = 85.0;  // alpha_p
  double kc = 0.3;                // gravicentrism k_c
  double leafSize_m = 0.2;        // l_l
  double leafDensity = 5.0;       // rho_l, leaves per terminal segment
  LeafDistribution leafDistribution = LeafDistribution::Spiral;  // l_type
  int lod = 0;  // l_LOD, the paper's level of detail (default --lod)
  LocalGraphs graphs;
};

// EcoMod's wind parameters, which bend every generator's trees (model/wind.hpp).
struct WindParams {
  double directed_wg = 0.0;             // w_g, degrees of tilt per unit strand fraction
  double undirected_ws = 0.0;           // w_s, degrees of sway per metre of base branch
  glm::dvec3 direction{0.0, 1.0, 0.0};  // w, toward which the wind blows, tree frame (y up)
  double flexibility = 1.0;             // k_f; sway scales with (1 - k_f)
};

// Differences between individuals of one species (not in the paper; see docs/model.md).
struct Variation {
  double branchAngle = 0.08;     // relative jitter of the branching angle
  double phyllotaxis_deg = 8.0;  // jitter of alpha_p, degrees
  double length = 0.08;          // relative jitter of the active length
};

struct Appearance {
  glm::vec3 barkColor{0.45f, 0.43f, 0.40f};  // sRGB in [0, 1]
  glm::vec3 leafColor{0.20f, 0.42f, 0.12f};
  LeafShape leafShape = LeafShape::Broadleaf;
  double barkRoughness = 0.5;  // 0 smooth (beech) .. 1 deeply furrowed (old pine)
};

// Which generator builds the species' trees (DESIGN.md: every generator makes a
// TreeSkeleton).
enum class TreeGenerator { Strand, LSystem };

struct LSystem;

// generator = "lsystem": an RL-system grammar (docs/lsystems.md) instead of [strand].
struct LSystemTree {
  std::filesystem::path grammarFile;
  std::shared_ptr<const LSystem> grammar;  // read with the species, so errors come early
  int iterations = 5;                      // derivation steps of a mature tree (age 1)
  double unit_m = 1.0;                     // metres per turtle unit
};

struct Species {
  std::string name;
  std::string latinName;
  std::vector<std::string> commonNames;  // other names it is called by ("hazel")
  // Whether `name` is its name or one of its common names, ignoring case.
  bool isCalled(std::string_view name) const;
  std::filesystem::path file;
  TreeGenerator generator = TreeGenerator::Strand;
  StrandParams strand;  // the strand model's parameters; defaults for L-system species
  LSystemTree lsystem;
  WindParams wind;  // from [strand] or [lsystem]
  Variation variation;
  Appearance appearance;
};

// Reads a species file but its [ecology]; unknown keys, wrong types and out-of-range values
// throw InputError with the file, line and key.
Species loadSpecies(const std::filesystem::path& file);

}  // namespace eco
