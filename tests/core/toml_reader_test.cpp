#include "core/toml_reader.hpp"

#include <gtest/gtest.h>

namespace eco {
namespace {

// Runs `body` and returns the InputError it throws (fails the test if none).
template <typename Body>
InputError inputErrorOf(Body body) {
  try {
    body();
  } catch (const InputError& error) {
    return error;
  }
  ADD_FAILURE() << "expected an InputError";
  return InputError({}, "none");
}

}  // namespace

TEST(TomlReader, ReadsValuesAndDefaults) {
  TomlDocument doc =
      TomlDocument::parse("a = 2\nb = 2.5\nname = \"x\"\nflag = true\nv = [1, 2.5, 3]\n", "t.toml");
  TomlTable root = doc.root();
  EXPECT_DOUBLE_EQ(root.number("a"), 2.0);  // integers are numbers too
  EXPECT_DOUBLE_EQ(root.number("b"), 2.5);
  EXPECT_EQ(root.integer("a"), 2);
  EXPECT_EQ(root.string("name"), "x");
  EXPECT_TRUE(root.boolean("flag"));
  EXPECT_EQ(root.numbers("v", 3), (std::vector<double>{1.0, 2.5, 3.0}));
  EXPECT_DOUBLE_EQ(root.number("missing", 7.0), 7.0);
  EXPECT_NO_THROW(root.finish());
}

TEST(TomlReader, NumberListsHaveAnyLength) {
  TomlDocument doc =
      TomlDocument::parse("v = [60, 80.5]\nw = [3]\ne = []\nx = [1, \"a\"]\n", "t.toml");
  TomlTable root = doc.root();
  EXPECT_EQ(root.numberList("v"), (std::vector<double>{60.0, 80.5}));
  EXPECT_EQ(root.numberList("w", {}, {0.0, 5.0}), std::vector<double>{3.0});
  EXPECT_EQ(root.numberList("none", std::vector<double>{1.0}), std::vector<double>{1.0});
  EXPECT_STREQ(inputErrorOf([&] { root.numberList("e"); }).what(),
               "t.toml:3: e: expected an array of one or more numbers");
  EXPECT_EQ(inputErrorOf([&] { root.numberList("x"); }).where().line, 4);
  EXPECT_NE(std::string(inputErrorOf([&] {
                          root.numberList("v", {}, {0.0, 70.0});
                        }).what())
                .find("outside [0, 70]"),
            std::string::npos);
}

TEST(TomlReader, UnknownKeyNamesItsLine) {
  TomlDocument doc = TomlDocument::parse("a = 1\n\n[t]\nb = 2\ntypo = 3\n", "s.toml");
  TomlTable root = doc.root();
  root.number("a");
  std::optional<TomlTable> t = root.table("t");
  t->number("b");
  InputError error = inputErrorOf([&] { t->finish(); });
  EXPECT_EQ(error.where().line, 5);
  EXPECT_EQ(error.where().key, "t.typo");
  EXPECT_STREQ(error.what(), "s.toml:5: t.typo: unknown key");
}

TEST(TomlReader, WrongTypeAndRangeAndMissing) {
  TomlDocument doc = TomlDocument::parse("a = \"five\"\nb = -1\nc = 1.5\n", "s.toml");
  TomlTable root = doc.root();
  InputError wrongType = inputErrorOf([&] { root.number("a"); });
  EXPECT_EQ(wrongType.where().line, 1);
  EXPECT_NE(std::string(wrongType.what()).find("expected a number"), std::string::npos);
  InputError range = inputErrorOf([&] { root.number("b", {}, {0.0, 1.0}); });
  EXPECT_EQ(range.where().line, 2);
  EXPECT_NE(std::string(range.what()).find("outside [0, 1]"), std::string::npos);
  InputError notInteger = inputErrorOf([&] { root.integer("c"); });
  EXPECT_EQ(notInteger.where().line, 3);
  InputError missing = inputErrorOf([&] { root.number("nothere"); });
  EXPECT_NE(std::string(missing.what()).find("missing required key"), std::string::npos);
}

TEST(TomlReader, PolylineErrorsPointAtTheBadPoint) {
  TomlDocument doc = TomlDocument::parse(
      "p = [\n  [0, 1],\n  [5, 2],\n  [3, 4],\n]\nq = [[0, 9]]\nr = [1, 2]\n", "p.toml");
  TomlTable root = doc.root();
  InputError unsorted = inputErrorOf([&] { root.polyline("p"); });
  EXPECT_EQ(unsorted.where().line, 4);
  EXPECT_NE(std::string(unsorted.what()).find("sorted"), std::string::npos);
  InputError range = inputErrorOf([&] { root.polyline("q", {0.0, 2.0}); });
  EXPECT_EQ(range.where().line, 6);
  InputError shape = inputErrorOf([&] { root.polyline("r"); });
  EXPECT_EQ(shape.where().line, 7);
}

// TOML spells inf and nan; no setting takes them, whatever its range, and a polyline's
// abscissa is checked before the polyline is built.
TEST(TomlReader, NonFiniteNumbersAreInputErrors) {
  TomlDocument doc = TomlDocument::parse(
      "a = inf\nb = -inf\nc = nan\nd = [1.0, inf, 0.0]\np = [[0, 1], [nan, 2]]\n"
      "q = [[0, 1], [1, inf]]\n",
      "n.toml");
  TomlTable root = doc.root();
  for (const char* key : {"a", "b", "c"}) {
    InputError error = inputErrorOf([&] { root.number(key); });
    EXPECT_NE(std::string(error.what()).find("not a finite number"), std::string::npos) << key;
  }
  EXPECT_EQ(inputErrorOf([&] { root.numbers("d", 3); }).where().line, 4);
  InputError abscissa = inputErrorOf([&] { root.polyline("p"); });
  EXPECT_EQ(abscissa.where().line, 5);
  EXPECT_NE(std::string(abscissa.what()).find("not a pair of finite numbers"), std::string::npos);
  EXPECT_EQ(inputErrorOf([&] { root.polyline("q"); }).where().line, 6);
}

TEST(TomlReader, PointsInAnyOrderAndATablesKeys) {
  TomlDocument doc = TomlDocument::parse(
      "p = [[5, 1], [0, 2],\n  [3, -4]]\nq = [[1, 1]]\n[mix]\nbeech = 0.7\nmaple = 0.3\n",
      "k.toml");
  TomlTable root = doc.root();
  const std::vector<TomlPoint> p = root.points("p", 3);
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p[0].x, 5.0);
  EXPECT_EQ(p[2].y, -4.0);
  EXPECT_EQ(p[2].line, 2);
  InputError few = inputErrorOf([&] { root.points("q", 2); });
  EXPECT_NE(std::string(few.what()).find("expected at least 2 points, got 1"), std::string::npos);
  EXPECT_EQ(root.table("mix")->keys(), (std::vector<std::string>{"beech", "maple"}));
}

TEST(TomlReader, SyntaxErrorsAndMissingFiles) {
  InputError syntax = inputErrorOf([] { TomlDocument::parse("a = 1\nb = = 2\n", "bad.toml"); });
  EXPECT_EQ(syntax.where().file, "bad.toml");
  EXPECT_EQ(syntax.where().line, 2);
  InputError missing = inputErrorOf([] { TomlDocument::load("/nonexistent/x.toml"); });
  EXPECT_STREQ(missing.what(), "/nonexistent/x.toml: cannot open file");
}

TEST(TomlReader, ArraysOfTables) {
  TomlDocument doc = TomlDocument::parse("[[s]]\nf = 1\n[[s]]\nf = 2\n", "a.toml");
  TomlTable root = doc.root();
  std::vector<TomlTable> tables = root.tables("s");
  ASSERT_EQ(tables.size(), 2u);
  EXPECT_DOUBLE_EQ(tables[1].number("f"), 2.0);
  EXPECT_EQ(tables[1].where("f").key, "s[1].f");
}

}  // namespace eco
