#include "model/design/edit_script.hpp"

#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "model/species_writer.hpp"
#include "test_support.hpp"

namespace eco {
namespace {

std::string errorOf(const std::string& script) {
  try {
    DesignSession session(test::loadNamed("beech"));
    applyEditScript(loadEditScript(test::writeTemporary("edits", script)), session);
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

std::string savedText(const std::string& script) {
  DesignSession session(test::loadNamed("beech"));
  applyEditScript(loadEditScript(test::writeTemporary("edits", script)), session);
  return speciesToml(session.species(), "");
}

constexpr const char* kBroaderBeech = R"(
[[edit]]
set = "kc"
value = 0.45
[[edit]]
graph = "alpha_g_deg"
add = [4]
[[edit]]
graph = "alpha_g_deg"
move = 1
to = [4.25, 62]
[[edit]]
graph = "min_length_g"
remove = 1
[[edit]]
undo = true
[[edit]]
redo = true
[[edit]]
set = "leaf_distribution"
value = "bunched"
[[edit]]
set = "wind_direction"
value = [0.2, 1, 0]
[hint]
graph = "alpha_g_deg"
point = 1
)";

}  // namespace

TEST(EditScript, AppliesEachEditInOrder) {
  DesignSession session(test::loadNamed("beech"));
  const EditScript script = loadEditScript(test::writeTemporary("edits", kBroaderBeech));
  ASSERT_EQ(script.edits.size(), 8u);
  EXPECT_EQ(script.edits[2].where.line, 9);
  applyEditScript(script, session);
  const Species& s = session.species();
  EXPECT_EQ(s.strand.kc, 0.45);
  ASSERT_EQ(s.strand.graphs.alphaG.points().size(), 3u);
  EXPECT_EQ(s.strand.graphs.alphaG.points()[1].x, 4.25);
  EXPECT_EQ(s.strand.graphs.alphaG.points()[1].y, 62.0);
  EXPECT_EQ(s.strand.graphs.minLenG.points().size(), 2u);  // removed, undone, redone
  EXPECT_EQ(s.strand.leafDistribution, LeafDistribution::Bunched);
  EXPECT_EQ(s.wind.direction, glm::dvec3(0.2, 1, 0));
  ASSERT_TRUE(script.hint.has_value());
  EXPECT_EQ(script.hint->graph, LocalGraph::AlphaG);
  EXPECT_EQ(script.hint->point, 1);
}

TEST(EditScript, TheSameScriptGivesTheSameSavedFileEveryTime) {
  const std::string first = savedText(kBroaderBeech);
  EXPECT_EQ(savedText(kBroaderBeech), first);
  EXPECT_NE(first.find("kc = 0.45"), std::string::npos) << first;
  EXPECT_NE(first.find("alpha_g_deg = [[0.0, 45.0], [4.25, 62.0], [15.0, 45.0]]"),
            std::string::npos)
      << first;
}

TEST(EditScript, BadEntriesNameTheirLineAndKey) {
  EXPECT_NE(errorOf("[[edit]]\nset = \"kcc\"\nvalue = 1\n")
                .find("edits.toml:2: edit[0].set: unknown "
                      "parameter 'kcc': did you mean 'kc'?"),
            std::string::npos)
      << errorOf("[[edit]]\nset = \"kcc\"\nvalue = 1\n");
  EXPECT_NE(
      errorOf("[[edit]]\ngraph = \"ks_q\"\nremove = 0\n").find(":2: edit[0].graph: unknown graph"),
      std::string::npos);
  EXPECT_NE(errorOf("[[edit]]\ngraph = \"ks_g\"\nremove = 5\n")
                .find(":2: edit[0].graph: ks_g has no point 5"),
            std::string::npos);
  EXPECT_NE(errorOf("[[edit]]\ngraph = \"ks_g\"\n").find("exactly one of move"), std::string::npos);
  EXPECT_NE(errorOf("[[edit]]\nundo = true\n").find(":2: edit[0].undo: there is no edit to undo"),
            std::string::npos);
  EXPECT_NE(errorOf("[[edit]]\nset = \"kc\"\nvalue = 1\nextra = 2\n").find("extra"),
            std::string::npos);
  EXPECT_NE(errorOf("[[edit]]\nset = \"leaf_distribution\"\nvalue = \"round\"\n")
                .find("unknown leaf distribution 'round'"),
            std::string::npos);
  EXPECT_NE(errorOf("[hint]\ngraph = \"ks_g\"\npoint = 0\nsegment = 0\n").find("not both"),
            std::string::npos);
}

}  // namespace eco
