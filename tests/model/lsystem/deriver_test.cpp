#include "model/lsystem/deriver.hpp"

#include <map>

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "core/error.hpp"
#include "model/lsystem/parser.hpp"

namespace eco {
namespace {

std::string derived(const LSystem& system, int iterations, std::uint64_t seed = 1) {
  DeriveOptions options;
  options.iterations = iterations;
  options.seed = seed;
  return toString(derive(system, options));
}

std::string derived(const std::string& text, int iterations, std::uint64_t seed = 1) {
  return derived(parseLSystem(text, "test.lsys"), iterations, seed);
}

std::string grammar(const std::string& axiom, const std::string& rules,
                    const std::string& declarations = "") {
  return "SYSTEM\nDECLARATIONS\n" + declarations + "AXIOM\n" + axiom + "\nRULES\n" + rules +
         "\nEND.\n";
}

LSystem shipped(const std::string& name) {
  return loadLSystem(std::string(ECOFOREST_DATA_DIR) + "/lsystems/" + name + ".lsys");
}

// Green, section 2: with the first production chosen for A(1) and the second for A(5),
// A(1)B(3)A(5) => A(2)B(6)[A(3)]B(4). Every seed that makes those choices gives exactly
// that string, and the choices come with probabilities 0.4 and 0.6.
TEST(LSystemDeriver, GreensWorkedDerivation) {
  const LSystem green = shipped("green_example");
  int paperChoices = 0, firstRule = 0;
  constexpr int kSeeds = 4000;
  for (std::uint64_t seed = 1; seed <= kSeeds; ++seed) {
    const std::string s = derived(green, 1, seed);
    const bool firstA = s.rfind("A(2)", 0) == 0;
    const bool lastB = s.size() >= 4 && s.substr(s.size() - 4) == "B(4)";
    firstRule += firstA;
    if (firstA && lastB) {
      EXPECT_EQ(s, "A(2)B(6)[A(3)]B(4)");
      ++paperChoices;
    }
    // B(3) always has its two A neighbours in the input string, and 3 < 4.
    EXPECT_NE(s.find("B(6)[A(3)]"), std::string::npos) << s;
  }
  EXPECT_NEAR(static_cast<double>(firstRule) / kSeeds, 0.4, 0.03);
  EXPECT_NEAR(static_cast<double>(paperChoices) / kSeeds, 0.4 * 0.6, 0.03);
  EXPECT_EQ(derived(green, 1, 3), "A(2)B(6)[A(3)]B(4)");  // a seed with the paper's choices
}

TEST(LSystemDeriver, LectureMonopodialAndDichotomousDerivations) {
  const LSystem mono = shipped("lecture_monopodial");
  EXPECT_EQ(derived(mono, 0), "0");
  EXPECT_EQ(derived(mono, 1), "11[0]0");
  EXPECT_EQ(derived(mono, 2), "11[11[0]0]11[0]0");
  EXPECT_EQ(derived(mono, 3), "11[11[11[0]0]11[0]0]11[11[0]0]11[0]0");
  const LSystem dicho = shipped("lecture_dichotomous");
  EXPECT_EQ(derived(dicho, 1), "11[0][0]");
  EXPECT_EQ(derived(dicho, 2), "11[11[0][0]][11[0][0]]");
  EXPECT_EQ(derived(dicho, 3), "11[11[11[0][0]][11[0][0]]][11[11[0][0]][11[0][0]]]");
}

TEST(LSystemDeriver, AlgaeLengthsAreFibonacciNumbers) {
  const LSystem algae = parseLSystem(grammar("A", "A -> AB\nB -> A"), "algae.lsys");
  EXPECT_EQ(derived(algae, 0), "A");
  EXPECT_EQ(derived(algae, 4), "ABAABABA");
  std::vector<std::size_t> fibonacci{1, 1};
  while (fibonacci.size() < 30) fibonacci.push_back(fibonacci.end()[-1] + fibonacci.end()[-2]);
  for (int n = 0; n <= 25; ++n) {
    DeriveOptions options;
    options.iterations = n;
    EXPECT_EQ(derive(algae, options).size(), fibonacci[static_cast<std::size_t>(n) + 1]) << n;
  }
}

// ABOP p. 42: the parametric L-system
//   w: B(2)A(4,4);  A(x,y): y<=3 -> A(x*2,x+y);  A(x,y): y>3 -> B(x)A(x/y,0);
//   B(x): x<1 -> C;  B(x): x>=1 -> B(x-1)
TEST(LSystemDeriver, ParametricExampleOfABOPPage42) {
  const LSystem abop = parseLSystem(grammar("B(2)A(4,4)",
                                            "A(x,y): y<=3 -> A(x*2,x+y)\n"
                                            "A(x,y): y>3 -> B(x)A(x/y,0)\n"
                                            "B(x): x<1 -> C\n"
                                            "B(x): x>=1 -> B(x-1)"),
                                    "abop42.lsys");
  EXPECT_EQ(derived(abop, 1), "B(1)B(4)A(1,0)");
  EXPECT_EQ(derived(abop, 2), "B(0)B(3)A(2,1)");
  EXPECT_EQ(derived(abop, 3), "CB(2)A(4,3)");
  EXPECT_EQ(derived(abop, 4), "CB(1)A(8,7)");
  EXPECT_EQ(derived(abop, 5), "CB(0)B(8)A(1.1428571428571428,0)");
}

// ABOP section 1.6.2: in ABC[DE][SG[HI[JK]L]MNO] the production BC < S > G[H]M applies to
// S; the left context steps over [DE] and out of S's branch, the right context over
// [I[JK]L] inside G's branch.
TEST(LSystemDeriver, BracketAwareContextsOnHandMadeStrings) {
  const std::string string = "ABC[DE][SG[HI[JK]L]MNO]";
  EXPECT_EQ(derived(grammar(string, "BC < S > G[H]M -> X"), 1), "ABC[DE][XG[HI[JK]L]MNO]");
  EXPECT_EQ(derived(grammar(string, "DE < S -> X"), 1), string);  // a sibling branch
  EXPECT_EQ(derived(grammar(string, "S > GH -> X"), 1), string);  // H is in a sub-branch
  EXPECT_EQ(derived(grammar(string, "S > GM -> X"), 1), "ABC[DE][XG[HI[JK]L]MNO]");
  EXPECT_EQ(derived(grammar(string, "C < S -> X"), 1), "ABC[DE][XG[HI[JK]L]MNO]");
  EXPECT_EQ(derived(grammar(string, "L > M -> X"), 1), string);  // ] ends L's branch
  EXPECT_EQ(derived(grammar(string, "L > ]M -> X"), 1), "ABC[DE][SG[HI[JK]X]MNO]");
  EXPECT_EQ(derived(grammar(string, "G < H -> X"), 1), "ABC[DE][SG[XI[JK]L]MNO]");
  EXPECT_EQ(derived(grammar(string, "C < G -> X"), 1), string);  // S lies between
  // IGNORE: modules skipped by context matching.
  EXPECT_EQ(derived(grammar("AF+FB", "A < B -> X"), 1), "AF+FB");
  EXPECT_EQ(derived(grammar("AF+FB", "A < B -> X", "IGNORE F +\n"), 1), "AF+FX");
  // Context parameters bind like the predecessor's.
  EXPECT_EQ(derived(grammar("A(1)B(2)C(3)", "A(x) < B(y) > C(z) -> B(x+y+z)"), 1), "A(1)B(6)C(3)");
}

TEST(LSystemDeriver, AcropetalSignalOfABOPFigure131) {
  const LSystem signal = shipped("abop_1_31");
  EXPECT_EQ(derived(signal, 1), "Fa[+Fb]Fb[-Fa]Fa[+Fa]Fa");
  EXPECT_EQ(derived(signal, 2), "Fa[+Fa]Fa[-Fb]Fb[+Fa]Fa");
  EXPECT_EQ(derived(signal, 3), "Fa[+Fa]Fa[-Fa]Fa[+Fb]Fb");
}

TEST(LSystemDeriver, StochasticRuleFrequenciesMatchTheirProbabilities) {
  const LSystem plant = shipped("abop_1_27");
  std::map<std::string, int> counts;
  constexpr int kSeeds = 6000;
  for (std::uint64_t seed = 1; seed <= kSeeds; ++seed) ++counts[derived(plant, 1, seed)];
  ASSERT_EQ(counts.size(), 3u);
  EXPECT_NEAR(counts["F[+F]F[-F]F"] / double(kSeeds), 0.33, 0.02);
  EXPECT_NEAR(counts["F[+F]F"] / double(kSeeds), 0.33, 0.02);
  EXPECT_NEAR(counts["F[-F]F"] / double(kSeeds), 0.34, 0.02);
}

TEST(LSystemDeriver, MatchingUsesOneDeviatePerVariableAndSuccessorsFreshOnes) {
  // p < 0.5 and p >= 0.5 see the same deviate: exactly one of the two rules applies.
  const LSystem split = parseLSystem(
      grammar("A", "A : p < 0.5 -> L\nA : p >= 0.5 -> R", "CONTINUOUS p UNIFORM(0,1)\n"), "s");
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    const std::string s = derived(split, 1, seed);
    EXPECT_TRUE(s == "L" || s == "R") << s;
  }
  // Two occurrences in one successor draw two deviates.
  const LSystem two =
      parseLSystem(grammar("A", "A -> B(p)B(p)", "CONTINUOUS p UNIFORM(0,1)\n"), "two");
  DeriveOptions options;
  options.iterations = 1;
  const ModuleString s = derive(two, options);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_NE(s.param(0, 0), s.param(1, 0));
}

TEST(LSystemDeriver, NumItAndMaxItSplitTheDevelopmentIntoPhases) {
  const std::string text = grammar("A", "A : NumIt = MaxIt -> B\nA -> FA");
  EXPECT_EQ(derived(text, 1), "B");
  EXPECT_EQ(derived(text, 4), "FFFB");
}

TEST(LSystemDeriver, SwitchDerivesTheNextItemEachStep) {
  const std::string text = grammar("@Switch{A B C}", "A -> X\nB -> Y\nC -> Z");
  EXPECT_EQ(derived(text, 1), "X@Switch(1){ABC}");
  EXPECT_EQ(derived(text, 2), "XY@Switch(2){ABC}");
  EXPECT_EQ(derived(text, 3), "XYZ@Switch(0){ABC}");
  EXPECT_EQ(derived(text, 4), "XYZX@Switch(1){ABC}");
}

TEST(LSystemDeriver, PendulumDerivesItsListForwardThenBackward) {
  const std::string text = grammar("@Pendulum{A B C}", "A -> X\nB -> Y\nC -> Z");
  EXPECT_EQ(derived(text, 1), "XYZ@Pendulum(-1){ABC}");
  EXPECT_EQ(derived(text, 2), "XYZZYX@Pendulum(1){ABC}");
  EXPECT_EQ(derived(text, 3), "XYZZYXXYZ@Pendulum(-1){ABC}");
}

TEST(LSystemDeriver, RepetitionDerivesItsBodyCountTimes) {
  EXPECT_EQ(derived(grammar("@Repetition(3){F[+A]}", "A -> L"), 1), "F[+L]F[+L]F[+L]");
  EXPECT_EQ(derived(grammar("G@Repetition(0){F}G", ""), 1), "GG");
  // A random count: the number of copies follows the variable's distribution.
  const LSystem random =
      parseLSystem(grammar("@Repetition(n){F}", "", "DISCRETE n POISSON(4)\n"), "r");
  double sum = 0.0;
  constexpr int kSeeds = 3000;
  for (std::uint64_t seed = 1; seed <= kSeeds; ++seed) sum += derived(random, 1, seed).size();
  EXPECT_NEAR(sum / kSeeds, 4.0, 0.15);
}

TEST(LSystemDeriver, PruneRemovesTheRestOfItsBranch) {
  EXPECT_EQ(derived(grammar("F[A F[F]F]F A F F", "A -> %"), 1), "F[]F");
  EXPECT_EQ(derived(grammar("F[+F[A]F]G", "A -> %F"), 1), "F[+F[]F]G");
  ModuleString s;
  for (char c : std::string("F[+F%F[F]F]F%FF")) s.add(static_cast<Symbol>(c));
  EXPECT_TRUE(applyPruneModules(s));
  EXPECT_EQ(toString(s), "F[+F]F");
  EXPECT_FALSE(applyPruneModules(s));
}

TEST(LSystemDeriver, InterrogationModulesReceiveTheTurtleState) {
  const LSystem queries = parseLSystem(grammar("F(2)+(90)F(3)?P?H?U?L", ""), "q.lsys");
  DeriveOptions options;
  options.iterations = 1;
  const ModuleString s = derive(queries, options);
  ASSERT_EQ(s.size(), 7u);
  const double expected[4][3] = {{-3, 2, 0}, {-1, 0, 0}, {0, 0, 1}, {0, -1, 0}};
  for (std::size_t q = 0; q < 4; ++q)
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(s.param(3 + q, k), expected[q][k], 1e-12) << q;
}

TEST(LSystemDeriver, TheExplosionCapNamesTheProductionThatExploded) {
  const LSystem bomb =
      parseLSystem(grammar("A", "A -> B\nB -> BB\nB -> C", "MAXMODULES 1000\n"), "bomb.lsys");
  try {
    derived(bomb, 30);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 8);  // B -> BB
    EXPECT_NE(std::string(e.what()).find("derivation step 11 makes more than 1000 modules"),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("the production 'B -> BB' exploded"), std::string::npos)
        << e.what();
  }
  // A single Repetition cannot overrun the cap either.
  const LSystem repeat = parseLSystem(grammar("@Repetition(1e12){F}", ""), "repeat.lsys");
  try {
    derived(repeat, 1);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("would make more than 50000000 modules"),
              std::string::npos)
        << e.what();
  }
  // The same through the parallel path: many chunks, one cap.
  DeriveOptions options;
  options.iterations = 30;
  options.maxModules = 200000;
  EXPECT_THROW(derive(bomb, options), InputError);
}

TEST(LSystemDeriver, SameSeedSameStringOnAnyThreadCount) {
  const LSystem plant = shipped("abop_1_27");
  DeriveOptions options;
  options.iterations = 9;  // about 200000 modules: the parallel path
  options.seed = 11;
  std::string one, two;
  {
    tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    one = toString(derive(plant, options));
  }
  {
    tbb::global_control pair(tbb::global_control::max_allowed_parallelism, 2);
    two = toString(derive(plant, options));
  }
  EXPECT_GT(one.size(), 100000u);
  EXPECT_EQ(one, two);
  options.seed = 12;
  EXPECT_NE(toString(derive(plant, options)), one);
}

}  // namespace
}  // namespace eco
