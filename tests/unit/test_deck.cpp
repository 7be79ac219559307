// The keyword reader (src/deck): numbers, expressions, card formats, comments, parameters,
// includes, *END, *CASE blocks and the exact form of its error messages.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <unistd.h>
#include <array>
#include <atomic>
#include <bit>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <string>
#include <utility>

#include "deck/card.hpp"
#include "deck/deck.hpp"
#include "deck/expression.hpp"
#include "deck/number.hpp"
#include "model/build.hpp"
#include "temp_dir.hpp"
#include "util/error.hpp"

namespace fs = std::filesystem;
using crumple::util::InputError;
using Files = std::map<std::string, std::string>;  // a deck::MemorySource's files

namespace {

// A scratch folder per test, removed afterwards.
using crumple::testing::errorOf;
// Each test's files in a fresh folder, removed afterwards.
class TempDir : public crumple::testing::TempDir {
 public:
  TempDir() : crumple::testing::TempDir("crumple_test_deck") {}
};

// Fixed-format card text: each value right-aligned in its width.
std::string cols(std::initializer_list<std::pair<std::string, int>> fields) {
  std::string line;
  for (const auto& [v, w] : fields)
    line += std::string(static_cast<std::size_t>(w) - v.size(), ' ') + v;
  return line + "\n";
}

// A one-element model around `extra` keywords (free format keeps the tests short).
const char* kCube = R"(*KEYWORD
*NODE
1,0,0,0
2,1,0,0
3,1,1,0
4,0,1,0
5,0,0,1
6,1,0,1
7,1,1,1
8,0,1,1
*ELEMENT_SOLID
1,1,1,2,3,4,5,6,7,8
*PART
cube
1,1,1
*SECTION_SOLID
1,1
)";

// A deck of one file "x.k" and, apart from it, a keyword `name` written at line 1 with `lines`
// (the file and keyword a card test reads from).
struct OneKeyword {
  crumple::deck::Deck deck;
  crumple::deck::Keyword kw;
  OneKeyword(std::string name, std::vector<crumple::deck::DataLine> lines) {
    deck.files = {"x.k"};
    kw.name = std::move(name);
    kw.line = 1;
    kw.lines = std::move(lines);
  }
};

// Reads "main.k" with `text` from memory, beside the files in `more`.
crumple::deck::Deck memoryDeck(const std::string& text, Files more = {},
                               crumple::deck::ReadDeckOptions options = {}) {
  more["main.k"] = text;
  return crumple::deck::readDeck("main.k", crumple::deck::MemorySource(std::move(more)), options);
}

// `field` of the first card of keyword `k` of the deck, read as `label` of `spec`'s table.
double realOf(const crumple::deck::Deck& d, std::size_t k, std::string_view spec,
              std::string_view label, std::string_view field) {
  crumple::deck::CardCursor cur(d.keywords.at(k), d);
  return cur.read(crumple::deck::keywordSpec(spec).card(label)).real(field);
}

}  // namespace

TEST(DeckNumber, FortranAndCForms) {
  using crumple::deck::parseInteger;
  using crumple::deck::parseReal;
  EXPECT_DOUBLE_EQ(*parseReal("2.00000-3"), 2e-3);
  EXPECT_DOUBLE_EQ(*parseReal("1.5+2"), 150.0);
  EXPECT_DOUBLE_EQ(*parseReal("1.d-3"), 1e-3);
  EXPECT_DOUBLE_EQ(*parseReal("1.0D+02"), 100.0);
  EXPECT_DOUBLE_EQ(*parseReal(" 7.83000E-6 "), 7.83e-6);
  EXPECT_DOUBLE_EQ(*parseReal("+.5"), 0.5);
  EXPECT_DOUBLE_EQ(*parseReal("-3."), -3.0);
  EXPECT_DOUBLE_EQ(*parseReal("-1-3"), -1e-3);
  for (const char* bad : {"abc", "", "1e", "inf", "nan", "1.2.3", "1,0", "--1"})
    EXPECT_FALSE(parseReal(bad)) << bad;
  EXPECT_EQ(*parseInteger("42"), 42);
  EXPECT_EQ(*parseInteger("+5"), 5);
  EXPECT_EQ(*parseInteger("1.0"), 1);
  EXPECT_EQ(*parseInteger("1e3"), 1000);
  EXPECT_EQ(*parseInteger("2.+1"), 20);
  EXPECT_FALSE(parseInteger("1.5"));
  EXPECT_FALSE(parseInteger("x"));
}

TEST(DeckExpression, OperatorsFunctionsAndParameters) {
  using crumple::deck::evaluateExpression;
  auto none = [](std::string_view) -> std::optional<double> { return std::nullopt; };
  auto params = [](std::string_view n) -> std::optional<double> {
    if (n == "a") return 3.0;
    if (n == "b") return 4.0;
    return std::nullopt;
  };
  EXPECT_DOUBLE_EQ(evaluateExpression("1 + 2 * 3", none), 7.0);
  EXPECT_DOUBLE_EQ(evaluateExpression("(1 + 2) * 3", none), 9.0);
  EXPECT_DOUBLE_EQ(evaluateExpression("2 ** 3 ** 2", none), 512.0);  // right associative
  EXPECT_DOUBLE_EQ(evaluateExpression("-2**2", none), -4.0);
  EXPECT_DOUBLE_EQ(evaluateExpression("10 / 4 - 1", none), 1.5);
  EXPECT_DOUBLE_EQ(evaluateExpression("sqrt(a*a + b*b)", params), 5.0);
  EXPECT_DOUBLE_EQ(evaluateExpression("max(a, b, 2) + min(a, b)", params), 7.0);
  EXPECT_DOUBLE_EQ(evaluateExpression("&a * 2", params), 6.0);
  EXPECT_DOUBLE_EQ(evaluateExpression("abs(-2) + exp(0) + log(1) + sin(0) + cos(0) + tan(0)", none),
                   4.0);
  EXPECT_DOUBLE_EQ(evaluateExpression("1.5e2 + 1.d1", none), 160.0);
  using crumple::deck::ExpressionError;
  EXPECT_THROW(evaluateExpression("c + 1", params), ExpressionError);
  EXPECT_THROW(evaluateExpression("1 / 0", none), ExpressionError);
  EXPECT_THROW(evaluateExpression("(1 + 2", none), ExpressionError);
  EXPECT_THROW(evaluateExpression("foo(1)", none), ExpressionError);
  EXPECT_THROW(evaluateExpression("1 2", none), ExpressionError);
}

// The in-place reading of plain decimals (parseSimpleReal, Clinger's fast path) must give the
// bits std::from_chars gives, for the forms pre-processors write, and leave to the long way
// what it cannot read exactly.
TEST(DeckNumber, PlainDecimalsReadBitwiseAsFromChars) {
  using crumple::deck::parseReal;
  using crumple::deck::parseSimpleReal;
  std::mt19937_64 rng(19);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> power(-30, 30);
  int accepted = 0, total = 0;
  const auto check = [&](const std::string& text) {
    double want = 0;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), want);
    ASSERT_TRUE(ec == std::errc() && ptr == text.data() + text.size()) << text;
    double fast = 0;
    ++total;
    if (parseSimpleReal(text, fast)) {
      ++accepted;
      EXPECT_EQ(std::bit_cast<uint64_t>(fast), std::bit_cast<uint64_t>(want)) << text;
    }
    EXPECT_EQ(std::bit_cast<uint64_t>(*parseReal(text)), std::bit_cast<uint64_t>(want)) << text;
  };
  for (int k = 0; k < 20000; ++k) {
    const double x = mantissa(rng) * std::pow(10.0, power(rng));
    for (const char* f : {"{:.9g}", "{:.6E}", "{:.15g}", "{:.17g}", "{:.3f}", "{:.0f}"})
      check(fmt::format(fmt::runtime(f), x));
  }
  for (const char* t :
       {"0", "-0", "-0.0", "1.", ".5", "1.e5", "2.5E-03", "7.85e-6", "210.0", "1e22", "1e-22",
        "9007199254740993", "123456789012345678", "1e23", "0.1", "0.30000000000000004", "1E+2"})
    check(t);
  // Most of them take the fast path; 17 significant digits and large powers do not.
  EXPECT_GT(accepted, total / 2);
  double v = 0;
  for (const char* other : {"+1", "1.5-3", "1d3", "1e", "1e+", ".", "-", "1e400", "1 2", "0x10"})
    EXPECT_FALSE(parseSimpleReal(other, v)) << other;
}

// A card whose fields the fast fixed-column reading refuses (a Fortran exponent, a '+', an
// integral real in an integer field, blanks inside a number) reads as it always did.
TEST(DeckFormat, FixedCardsOutsideThePlainFormsReadAsBefore) {
  TempDir t;
  const auto p = t.write(
      "d.k",
      std::string(kCube) +
          "*MAT_ELASTIC\n"
          "         1    7.83-6    +207.0       0.3\n"
          "*NODE\n" +
          cols({{"+10", 8}, {"1.5D0", 16}, {"+2.0", 16}, {"-4.0E+00", 16}, {"1.0", 8}, {"0", 8}}));
  const auto m = crumple::model::readModel(p);
  ASSERT_EQ(m.nodes.size(), 9u);
  EXPECT_EQ(m.nodes.id.back(), 10);
  EXPECT_EQ(m.nodes.x.back()[0], 1.5);
  EXPECT_EQ(m.nodes.x.back()[1], 2.0);
  EXPECT_EQ(m.nodes.x.back()[2], -4.0);
  EXPECT_EQ(m.materials.at(0).rho, 7.83e-6);
  ASSERT_EQ(m.spcs.size(), 1u);  // TC 1.0 read as 1 (x)
  EXPECT_EQ(m.spcs[0].dofs, 0b000001);
}

TEST(DeckFormat, FixedNodeWidthsRunsOfDigitsAndFortranReals) {
  TempDir t;
  // *NODE is I8, 3E16, 2I8: fields touch without blanks between them.
  const auto p = t.write("d.k", std::string(kCube) +
                                    "*MAT_ELASTIC\n"
                                    "         17.83000E-6     207.0       0.3\n"
                                    "*NODE\n" +
                                    cols({{"10", 8},
                                          {"1.50000000", 16},
                                          {"2.00000-3", 16},
                                          {"-4.0", 16},
                                          {"1", 8},
                                          {"7", 8}}));
  const auto m = crumple::model::readModel(p);
  ASSERT_EQ(m.nodes.size(), 9u);
  EXPECT_EQ(m.nodes.id.back(), 10);
  EXPECT_DOUBLE_EQ(m.nodes.x.back()[0], 1.5);
  EXPECT_DOUBLE_EQ(m.nodes.x.back()[1], 2e-3);
  EXPECT_DOUBLE_EQ(m.nodes.x.back()[2], -4.0);
  EXPECT_DOUBLE_EQ(m.materials.at(0).rho, 7.83e-6);
  ASSERT_EQ(m.spcs.size(), 1u);  // TC 1 (x) and RC 7 (all rotations)
  EXPECT_EQ(m.spcs[0].node, 8);
  EXPECT_EQ(m.spcs[0].dofs, 0b111001);
}

TEST(DeckFormat, LongFormatBySuffixAndKeywordLine) {
  TempDir t;
  const std::string node20 =
      "                  11                 1.5                 2.5                 3.5\n";
  const auto a = t.write("a.k", std::string(kCube) + "*MAT_ELASTIC\n1,1,1,0.3\n*NODE +\n" + node20);
  EXPECT_DOUBLE_EQ(crumple::model::readModel(a).nodes.x.back()[2], 3.5);
  // LONG=Y for the whole file, "-" forcing the standard widths for one keyword.
  const auto b = t.write(
      "b.k", std::string("*KEYWORD LONG=Y\n") + (kCube + 9) + "*MAT_ELASTIC\n1,1,1,0.3\n*NODE\n" +
                 node20 + "*NODE -\n      12             1.0             2.0             3.0\n");
  const auto m = crumple::model::readModel(b);
  EXPECT_DOUBLE_EQ(m.nodes.x[m.nodeIndex(11)][1], 2.5);
  EXPECT_DOUBLE_EQ(m.nodes.x[m.nodeIndex(12)][2], 3.0);
}

TEST(DeckFormat, TextAfterTheKeywordName) {
  // A memory size after *KEYWORD, a remark after *PART (*CONTROL_SPH "carte de control" in
  // the SPH examples), a format suffix as its own word: none changes how the cards read.
  TempDir t;
  std::string cube = kCube + 9;
  cube.replace(cube.find("*PART\n"), 6, "*PART  some text\n");
  const auto p = t.write("d.k", "*KEYWORD 100000000\n" + cube +
                                    "*MAT_ELASTIC   steel, for now\n1,1,1,0.3\n*NODE %\n" +
                                    cols({{"12", 10}, {"1.5", 16}, {"2.5", 16}, {"3.5", 16}}));
  const auto d = crumple::deck::readDeck(p);
  EXPECT_EQ(d.keywords.at(2).name, "*PART");
  EXPECT_EQ(d.keywords.at(2).trailing, "some text");
  EXPECT_EQ(d.keywords.back().format, crumple::deck::Format::I10);
  EXPECT_EQ(d.keywords.at(0).format, crumple::deck::Format::Standard);
  const auto m = crumple::model::readModel(p);
  EXPECT_EQ(m.parts.at(0).title, "cube");
  EXPECT_DOUBLE_EQ(m.nodes.x[m.nodeIndex(12)][2], 3.5);
}

TEST(DeckFormat, FreeFormatCommentsBlankFieldsAndCase) {
  TempDir t;
  const auto p = t.write("d.k", std::string(kCube) +
                                    "$ a comment before\n"
                                    "*mat_elastic_title\n"
                                    "$ a comment between the title and card 1\n"
                                    "steel, with a comma in the title\n"
                                    "  $ an indented comment\n"
                                    "1,7.8e-9,,0.3\n");
  // E blank -> 0 -> error, proving that an empty free-format entry is a blank field.
  // (kCube's part 1 uses the material: the error names the element that makes it matter.)
  EXPECT_EQ(errorOf([&] { crumple::model::readModel(p); }),
            p.string() +
                ":23: *MAT_ELASTIC_TITLE card 1 field 3 (E): Young's modulus must be positive (the "
                "part is used by *ELEMENT_SOLID at " +
                p.string() + ":12)");
  const auto q = t.write(
      "e.k", std::string(kCube) + "*MAT_ELASTIC_TITLE\nsteel, with a comma\n1,7.8e-9,2e5,0.3\n");
  const auto m = crumple::model::readModel(q);
  EXPECT_EQ(m.materials.at(0).title, "steel, with a comma");
  EXPECT_DOUBLE_EQ(std::get<crumple::materials::Elastic::Params>(m.materials.at(0).law).E, 2e5);
}

TEST(DeckErrors, BadNumberNamesFileLineKeywordCardAndField) {
  TempDir t;
  const auto p = t.write("deck.k", std::string(kCube) +
                                       "*MAT_ELASTIC\n"
                                       "         1       7.8       abc       0.3\n");
  EXPECT_EQ(errorOf([&] { crumple::model::readModel(p); }),
            p.string() + ":19: *MAT_ELASTIC card 1 field 3 (E): 'abc' is not a number");
  const auto q = t.write(
      "int.k", std::string(kCube) + "*MAT_ELASTIC\n       1.5       7.8       1.0       0.3\n");
  EXPECT_EQ(errorOf([&] { crumple::model::readModel(q); }),
            q.string() + ":19: *MAT_ELASTIC card 1 field 1 (MID): '1.5' is not an integer");
}

TEST(DeckParameters, ValuesReferencesAndExpressions) {
  TempDir t;
  const auto p =
      t.write("d.k", std::string("*KEYWORD\n"
                                 "*PARAMETER\n"
                                 "R E       2.0+5     I mid     1         R nu      0.3\n"
                                 "*PARAMETER_EXPRESSION\n"
                                 "R rho     sqrt(4.0)*&nu*max(1, 2)\n"
                                 "I half    mid * 3 / 2\n") +
                         (kCube + 9) +
                         "*MAT_ELASTIC\n"
                         "      &mid      &rho        &E       &nu\n"
                         "*NODE\n" +
                         cols({{"9", 8}, {"-&E", 16}, {"0.0", 16}, {"0.0", 16}}) +
                         "*INITIAL_VELOCITY_NODE\n"
                         "&half,1,2,3\n");
  const auto m = crumple::model::readModel(p);
  const auto& mat = m.materials.at(0);
  EXPECT_EQ(mat.id, 1);
  EXPECT_DOUBLE_EQ(mat.rho, 1.2);
  EXPECT_DOUBLE_EQ(std::get<crumple::materials::Elastic::Params>(mat.law).E, 2e5);
  EXPECT_DOUBLE_EQ(m.nodes.x[m.nodeIndex(9)][0], -2e5);
  EXPECT_DOUBLE_EQ(m.initial_velocity[m.nodeIndex(1)][2], 3.0);  // half = int(1.5) = 1
  const auto q = t.write("u.k", std::string(kCube) + "*MAT_ELASTIC\n1,&rho,1,0.3\n");
  EXPECT_EQ(errorOf([&] { crumple::model::readModel(q); }),
            q.string() + ":19: *MAT_ELASTIC card 1 field 2 (RO): parameter 'rho' is not defined");
}

TEST(DeckParameters, DuplicationFlag) {
  TempDir t;
  auto deckWith = [&](const std::string& name, const std::string& dflag) {
    return t.write(name, "*KEYWORD\n" + dflag +
                             "*PARAMETER\nR ro      1.0\n*PARAMETER\nR ro      2.0\n" +
                             (kCube + 9) + "*MAT_ELASTIC\n1,&ro,1,0.3\n");
  };
  // Default (1): the first definition is kept, with a note.
  const auto m1 = crumple::model::readModel(deckWith("d1.k", ""));
  EXPECT_DOUBLE_EQ(m1.materials.at(0).rho, 1.0);
  ASSERT_FALSE(m1.ignored.empty());
  EXPECT_EQ(m1.ignored[0].field, "ro");
  EXPECT_DOUBLE_EQ(
      crumple::model::readModel(deckWith("d2.k", "*PARAMETER_DUPLICATION\n2\n")).materials[0].rho,
      2.0);
  EXPECT_DOUBLE_EQ(
      crumple::model::readModel(deckWith("d4.k", "*PARAMETER_DUPLICATION\n4\n")).materials[0].rho,
      2.0);
  EXPECT_DOUBLE_EQ(
      crumple::model::readModel(deckWith("d5.k", "*PARAMETER_DUPLICATION\n5\n")).materials[0].rho,
      1.0);
  const auto p3 = deckWith("d3.k", "*PARAMETER_DUPLICATION\n3\n");
  EXPECT_EQ(errorOf([&] { crumple::model::readModel(p3); }),
            p3.string() +
                ":7: *PARAMETER card 1 field 1 (PRMR1): parameter 'ro' is already defined at " +
                p3.string() + ":5 (*PARAMETER_DUPLICATION DFLAG=3)");
}

TEST(DeckParameters, NamesAreCaseInsensitive) {
  // Defined as tEnd, used as TEnd and &TEND (mainboltbexpl.k of the bolted-joint example).
  const auto d = memoryDeck(
      "*PARAMETER\nR     tEnd       5.0\n"
      "*PARAMETER_EXPRESSION\nR   dtPlot TEnd/100.0\n"
      "*PARAMETER\nR     TEND       7.0\n"
      "*CONTROL_TERMINATION\n&TEND\n");
  ASSERT_NE(d.parameter("tend"), nullptr);
  EXPECT_EQ(d.parameter("TEnd")->name, "tEnd");
  EXPECT_DOUBLE_EQ(d.parameter("DTPLOT")->value, 0.05);
  EXPECT_DOUBLE_EQ(realOf(d, 0, "*CONTROL_TERMINATION", "card 1", "ENDTIM"), 5.0);
  // Another spelling of the same name is a duplicate (DFLAG 1 keeps the first).
  ASSERT_EQ(d.notes.size(), 1u);
  EXPECT_EQ(d.notes[0].field, "TEND");
}

TEST(DeckParameters, ExpressionsAfterAnAmpersand) {
  // sinusoid.k (muscle example): expressions in the 20-wide *DEFINE_CURVE point fields;
  // eccentric.k: an expression that starts with a reference.
  const auto d = memoryDeck(
      "*PARAMETER\nR       tp       2.0R        a       4.0R        b       1.0\n"
      "*PARAMETER_EXPRESSION\n"
      "R rampLenS &A-&b\n"
      "R    third 1.0/3.0\n"
      "R    again &third\n"
      "*DEFINE_CURVE\n         4\n"
      "        &tp*0.500000     &a*-0.250000+&B\n"
      "*DEFINE_CURVE\n1+&A/8\n"
      "*DEFINE_CURVE\n-&a\n");
  EXPECT_DOUBLE_EQ(d.parameter("rampLenS")->value, 3.0);
  EXPECT_EQ(d.parameter("again")->value, 1.0 / 3.0);  // exactly: no digits lost on the way
  crumple::deck::CardCursor cur(d.keywords.at(0), d);
  const auto& spec = crumple::deck::keywordSpec("*DEFINE_CURVE");
  cur.read(spec.card("card 1"));
  const auto& point = cur.read(spec.card("point card"));
  EXPECT_DOUBLE_EQ(point.real("A1"), 1.0);
  EXPECT_DOUBLE_EQ(point.real("O1"), 0.0);
  EXPECT_EQ(errorOf([&] { realOf(d, 1, "*DEFINE_CURVE", "card 1", "LCID"); }),
            "main.k:11: *DEFINE_CURVE card 1 field 1 (LCID): '1+&A/8' = 1.5 is not an integer");
  EXPECT_DOUBLE_EQ(realOf(d, 2, "*DEFINE_CURVE", "card 1", "LCID"), -4.0);  // a plain reference
  const auto bad = memoryDeck("*DEFINE_CURVE\n&a*2\n");
  EXPECT_EQ(errorOf([&] { realOf(bad, 0, "*DEFINE_CURVE", "card 1", "LCID"); }),
            "main.k:2: *DEFINE_CURVE card 1 field 1 (LCID): expression '&a*2': parameter 'a' is "
            "not defined");
}

TEST(DeckParameters, TypeLetterGluedToTheNameInFreeAndFixedFormat) {
  // Run.k (hypervelocity impact template): "RA1,2251710e3", and RT defined but &t used -- the
  // reason that deck stopped was the case of the name (see NamesAreCaseInsensitive).
  const auto d = memoryDeck(
      "*PARAMETER\n"
      "RA1,2251710e3                                   \n"
      "RT,1.2E-5\n"
      "i n, 3,C  tag,steel\n"
      "RpathLenN0  1.000000R      dT      0.500I      k2         7\n"
      "*PARAMETER_EXPRESSION\n"
      "Rf_r, 2-&dt\n"
      "*CONTROL_TERMINATION\n"
      "&t            600000\n");
  EXPECT_DOUBLE_EQ(d.parameter("A1")->value, 2251710e3);
  EXPECT_EQ(d.parameter("N")->type, 'I');
  EXPECT_DOUBLE_EQ(d.parameter("n")->value, 3.0);
  EXPECT_EQ(d.parameter("tag")->text, "steel");
  EXPECT_DOUBLE_EQ(d.parameter("pathLenN0")->value, 1.0);
  EXPECT_DOUBLE_EQ(d.parameter("k2")->value, 7.0);
  EXPECT_DOUBLE_EQ(d.parameter("f_r")->value, 1.5);
  EXPECT_DOUBLE_EQ(realOf(d, 0, "*CONTROL_TERMINATION", "card 1", "ENDTIM"), 1.2e-5);
  EXPECT_DOUBLE_EQ(realOf(d, 0, "*CONTROL_TERMINATION", "card 1", "ENDCYC"), 600000.0);
}

TEST(DeckInclude, NestedRelativePathsAndSearchDirs) {
  TempDir t;
  t.write("mesh/nodes.k", "*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n*INCLUDE\nmore/top.k\n");
  t.write("mesh/more/top.k", "*NODE\n5,0,0,1\n6,1,0,1\n7,1,1,1\n8,0,1,1\n");
  t.write("lib/mat.k", "*MAT_ELASTIC\n1,1,1,0.3\n*END\nthis is not read\n");
  const auto p =
      t.write("main.k",
              "*KEYWORD\n*INCLUDE_PATH\nlib\n*INCLUDE\nmesh/nodes.k\n*INCLUDE\nmat.k\n"
              "*ELEMENT_SOLID\n1,1,1,2,3,4,5,6,7,8\n*PART\ncube\n1,1,1\n*SECTION_SOLID\n1\n");
  const auto m = crumple::model::readModel(p);
  EXPECT_EQ(m.nodes.size(), 8u);
  EXPECT_EQ(m.materials.size(), 1u);
  EXPECT_EQ(m.materials[0].where.file, (t.path() / "lib/mat.k").string());
  const auto q = t.write("missing.k", "*KEYWORD\n*INCLUDE\nnope.k\n");
  EXPECT_EQ(errorOf([&] { crumple::model::readModel(q); }),
            q.string() + ":2: *INCLUDE: cannot open 'nope.k' (tried " +
                (t.path() / "nope.k").string() + ")");
  EXPECT_EQ(errorOf([&] { crumple::model::readModel(t.path() / "absent.k"); }),
            (t.path() / "absent.k").string() + ": cannot open the file");
}

TEST(DeckInclude, CyclesAreNamedWithTheirChain) {
  TempDir t;
  t.write("sub/unrelated.k", "");
  t.write("b.k", "*KEYWORD\n*INCLUDE\nsub/../a.k\n");
  const auto a = t.write("a.k", "*KEYWORD\n*INCLUDE\nb.k\n");
  // The second spelling of a.k is the same file: recognised by its canonical path.
  EXPECT_EQ(errorOf([&] { crumple::deck::readDeck(a); }),
            (t.path() / "b.k").string() +
                ":3: *INCLUDE card 1 field 1 (FILENAME): include cycle: " + a.string() + " -> " +
                (t.path() / "b.k").string() + " -> " + (t.path() / "a.k").string());
  const auto self = t.write("self.k", "*INCLUDE\nself.k\n");
  EXPECT_NE(errorOf([&] { crumple::deck::readDeck(self); }).find("include cycle"),
            std::string::npos);
  // Including the same file twice, one after the other, is no cycle.
  t.write("nodes.k", "*NODE\n1,0,0,0\n");
  const auto twice = t.write("twice.k", "*INCLUDE\nnodes.k\n*INCLUDE\nnodes.k\n");
  EXPECT_EQ(crumple::deck::readDeck(twice).keywords.size(), 2u);
}

TEST(DeckInclude, WindowsPathsFallBackToTheFileNameBesideTheDeck) {
  // A drive path written on another machine (main.k of the tensile-specimen example), a
  // relative path with backslashes, and a file found only in an *INCLUDE_PATH folder.
  const crumple::deck::MemorySource source(
      Files{{"model/main.k",
             "*INCLUDE_PATH\nrun\n*INCLUDE\nD:\\work\\model\\nodes.k\n"
             "..\\model\\lib\\mat.k\nC:\\old\\spc.k\n"},
            {"model/nodes.k", "*NODE\n1,0,0,0\n"},
            {"model/lib/mat.k", "*MAT_ELASTIC\n1,1,1,0.3\n"},
            {"model/run/spc.k", "*BOUNDARY_SPC_NODE\n1,0,1,1,1\n"}});
  const auto deck = crumple::deck::readDeck("model/main.k", source);
  ASSERT_EQ(deck.keywords.size(), 3u);
  EXPECT_EQ(deck.files.at(deck.keywords[0].file), "model/nodes.k");
  EXPECT_EQ(deck.files.at(deck.keywords[1].file), "model/lib/mat.k");
  EXPECT_EQ(deck.files.at(deck.keywords[2].file), "model/run/spc.k");
  // Nothing found: every path tried is named.
  EXPECT_EQ(errorOf([&] { memoryDeck("*INCLUDE_PATH\nlib\n*INCLUDE\nD:\\x\\gone.k\n"); }),
            "main.k:3: *INCLUDE: cannot open 'D:\\x\\gone.k' (tried gone.k, lib/gone.k)");
  EXPECT_EQ(errorOf([&] { memoryDeck("*INCLUDE\nsub\\gone.k\n"); }),
            "main.k:1: *INCLUDE: cannot open 'sub\\gone.k' (tried sub/gone.k, gone.k)");
}

TEST(DeckInclude, OneNamePerLineAndNamesWithBlanks) {
  // input.k of the MAT_106 examples: one *INCLUDE, one file per line. A name may hold blanks
  // ("Neo-Hookean - Tensor/"): the line is one name, as LS-DYNA reads it.
  const Files files{{"mesh.k", "*NODE\n1,0,0,0\n"},
                    {"my folder/mat 1.k", "*MAT_ELASTIC\n1,1,1,0.3\n"}};
  const auto d = memoryDeck("*INCLUDE\nmesh.k\n$ a comment between\nmy folder/mat 1.k\n", files);
  ASSERT_EQ(d.keywords.size(), 2u);
  EXPECT_EQ(d.keywords[1].name, "*MAT_ELASTIC");
  EXPECT_EQ(errorOf([&] { memoryDeck("*INCLUDE\nmesh.k mat.k\n", files); }),
            "main.k:1: *INCLUDE: cannot open 'mesh.k mat.k' (tried mesh.k mat.k); *INCLUDE "
            "takes one file name per line");
}

TEST(DeckInclude, IncludePathRelativeIsRelativeToTheMainDeck) {
  // active_force_length_06.k of the VEXAT muscle example: the main deck includes a file one
  // folder up, whose *INCLUDE_PATH_RELATIVE ../../../common/ only makes sense from the main
  // deck's folder.
  const Files files{
      {"ex/umat/apfl/afl06/main.k", "*INCLUDE_PATH_RELATIVE\n../\n*INCLUDE\n../apfl.k\n"},
      {"ex/umat/apfl/apfl.k", "*INCLUDE_PATH_RELATIVE\n../../../common/\n*INCLUDE\nparams.k\n"},
      {"ex/common/params.k", "*PARAMETER\nR        a       1.0\n"}};
  const auto d =
      crumple::deck::readDeck("ex/umat/apfl/afl06/main.k", crumple::deck::MemorySource(files));
  ASSERT_NE(d.parameter("a"), nullptr);
  EXPECT_EQ(d.parameter("a")->where.file, "ex/common/params.k");
}

TEST(DeckSource, MemoryFilesOnlyAndNothingFromDisk) {
  using crumple::deck::MemorySource;
  TempDir t;
  const auto on_disk = t.write("real.k", "*NODE\n1,0,0,0\n");
  const MemorySource files(
      {{"main.k", "*INCLUDE\ninc/part.k\n*INCLUDE\n" + on_disk.string() + "\n"},
       {"inc/part.k", "*NODE\n2,1,0,0\n"}});
  // The include in memory is found; the absolute path of a real file is not (nor its name
  // beside the deck).
  EXPECT_EQ(errorOf([&] { crumple::deck::readDeck("main.k", files); }),
            "main.k:3: *INCLUDE: cannot open '" + on_disk.string() + "' (tried " +
                on_disk.string() + ", real.k)");
  const MemorySource one(Files{{"x.k", "*NODE\n1,0,0,0\n"}});
  EXPECT_EQ(crumple::deck::readDeck("x.k", one).keywords.size(), 1u);
  EXPECT_EQ(errorOf([&] { crumple::deck::readDeck("y.k", one); }), "y.k: cannot open the file");
}

TEST(DeckLines, LongLinesAndBinaryDataAreRefused) {
  using crumple::deck::kMaxLineLength;
  using crumple::deck::MemorySource;
  const std::string at_cap(kMaxLineLength, 'x');
  // A title exactly at the cap is read; one character more is refused at its line.
  EXPECT_EQ(crumple::deck::readDeck("a.k", MemorySource(Files{{"a.k", "*TITLE\n" + at_cap + "\n"}}))
                .keywords[0]
                .lines[0]
                .text.size(),
            kMaxLineLength);
  EXPECT_EQ(
      errorOf([&] {
        crumple::deck::readDeck("a.k", MemorySource(Files{{"a.k", "*TITLE\n" + at_cap + "y"}}));
      }),
      "a.k:2: line longer than 65536 characters: this is not a keyword deck (or a line end "
      "is missing)");
  // Control characters other than tab, form feed, vertical tab and ^Z are binary data; CR LF
  // line ends and bytes of UTF-8 text are not.
  EXPECT_EQ(errorOf([&] {
              crumple::deck::readDeck("b.k", MemorySource(Files{{"b.k", "*NODE\n1,0,0\x01,0\n"}}));
            }),
            "b.k:2: byte 0x01 in column 6: binary data, not a keyword deck (text)");
  EXPECT_EQ(
      errorOf([&] {
        crumple::deck::readDeck("b.k", MemorySource(Files{{"b.k", std::string("*NODE\n\0", 8)}}));
      }),
      "b.k:2: byte 0x00 in column 1: binary data, not a keyword deck (text)");
  const auto ok = crumple::deck::readDeck(
      "c.k", MemorySource(Files{{"c.k", "*TITLE\r\nK\xc3\xa4se\tbox\f\r\n\x1a"}}));
  EXPECT_EQ(ok.keywords[0].lines[0].text, "K\xc3\xa4se\tbox\f");
  // The text is scanned eight bytes at a time: a bad byte in any place of a word, DEL, and a
  // carriage return before the line's end are found in the line and column they are in.
  const std::string row = "       1             0.0             0.0             0.0\n";
  for (const std::size_t column : {1u, 7u, 8u, 9u, 16u, 17u, 55u}) {
    for (const char bad : {'\x01', '\x7f', '\r', '\x1f'}) {
      std::string line = row;
      line[column - 1] = bad;
      const std::string text = "*NODE\n" + row + row + line + row;
      EXPECT_EQ(errorOf([&] {
                  crumple::deck::readDeck("d.k", MemorySource(Files{{"d.k", text}}));
                }),
                fmt::format("d.k:4: byte 0x{:02x} in column {}: binary data, not a keyword deck "
                            "(text)",
                            static_cast<unsigned char>(bad), column))
          << column;
    }
  }
  // Every byte in a word's first, last and a middle place: a control byte but tab, form feed,
  // vertical tab and ^Z is binary, and so are DEL and a lone carriage return; any other byte,
  // UTF-8 and Latin-1 text included, is read as written.
  for (int byte = 0; byte < 256; ++byte) {
    const auto u = static_cast<unsigned char>(byte);
    if (u == '\n' || u == '$' || u == '*') continue;  // a line end, a comment, a keyword
    const bool binary = (u < 0x20 && u != '\t' && u != '\f' && u != '\v' && u != 0x1a) || u == 0x7f;
    for (const std::size_t column : {1u, 8u, 12u, 55u}) {
      std::string line = row;
      line[column - 1] = static_cast<char>(u);
      const std::string text = "*NODE\n" + row + line + row;
      const std::string expected =
          binary ? fmt::format(
                       "d.k:3: byte 0x{:02x} in column {}: binary data, not a keyword "
                       "deck (text)",
                       byte, column)
                 : "";
      std::string read;
      EXPECT_EQ(errorOf([&] {
                  read = crumple::deck::readDeck("d.k", MemorySource(Files{{"d.k", text}}))
                             .keywords.at(0)
                             .lines.at(1)
                             .text;
                }),
                expected)
          << byte << " " << column;
      if (!binary) {
        EXPECT_EQ(read, line.substr(0, line.size() - 1)) << byte << " " << column;
      }
    }
  }
}

TEST(DeckLines, EncryptedIncludeIsNamedAsSuch) {
  // keyfile_include2.key (qd-cae test deck): plain keywords, then a PGP block of cipher bytes.
  const Files files{{"enc.key", "*NODE\n1,0,0,0\n-----BEGIN PGP MESSAGE-----\n\x85\x01\x0c\n"}};
  EXPECT_EQ(errorOf([&] { memoryDeck("*INCLUDE\nenc.key\n", files); }),
            "enc.key:3: encrypted (PGP) input cannot be read");
}

TEST(DeckErrors, CollectModeRecordsEachBadIncludeOrParameterAndReadsOn) {
  const Files files{{"good.k", "*NODE\n1,0,0,0\n"},
                    {"loop.k", "*INCLUDE\nloop.k\n*NODE\n2,0,0,0\n"},
                    {"bin.k", "*NODE\n3,0,0,0\n*NODE\n4,0\x01\n*NODE\n5,0,0,0\n"}};
  const std::string main =
      "*PARAMETER\n"
      "R        a       1.0R        b       abcR        c       3.0\n"  // 2
      "*PARAMETER_EXPRESSION\n"
      "R        d &a+&zz\n"  // 4
      "R        e &a+&c\n"
      "*INCLUDE\n"  // 6
      "missing.k\n"
      "loop.k\n"
      "bin.k\n"
      "good.k\n"
      "*NODE\n9,0,0,0\n";
  const auto d = memoryDeck(main, files, {.collect_errors = true});
  const std::vector<std::string> expected{
      "main.k:2: *PARAMETER card 1 field 4 (VAL2): 'abc' is not a number",
      "main.k:4: *PARAMETER_EXPRESSION card 1 field 2 (EXPRESSION): expression '&a+&zz': "
      "parameter 'zz' is not defined",
      "main.k:6: *INCLUDE: cannot open 'missing.k' (tried missing.k)",
      "loop.k:2: *INCLUDE card 1 field 1 (FILENAME): include cycle: loop.k -> loop.k",
      "bin.k:4: byte 0x01 in column 4: binary data, not a keyword deck (text)"};
  EXPECT_EQ(d.errors, expected);
  EXPECT_DOUBLE_EQ(d.parameter("c")->value, 3.0);
  EXPECT_DOUBLE_EQ(d.parameter("e")->value, 4.0);
  EXPECT_EQ(d.parameter("b"), nullptr);
  // Nodes 2 (after the cycle in loop.k), 3 (before the bad line of bin.k), 1 and 9 are read.
  std::vector<std::string> nodes;
  for (const auto& k : d.keywords) nodes.emplace_back(k.lines.at(0).text);
  EXPECT_EQ(nodes, (std::vector<std::string>{"2,0,0,0", "3,0,0,0", "1,0,0,0", "9,0,0,0"}));
  // Without the option the first error is thrown, as before; the main file is always thrown.
  EXPECT_EQ(errorOf([&] { memoryDeck(main, files); }), expected[0]);
  EXPECT_EQ(errorOf([&] {
              crumple::deck::readDeck("none.k", crumple::deck::MemorySource(files),
                                      {.collect_errors = true});
            }),
            "none.k: cannot open the file");
  EXPECT_EQ(errorOf([&] { memoryDeck("*NODE\n1,\x02\n", {}, {.collect_errors = true}); }),
            "main.k:2: byte 0x02 in column 3: binary data, not a keyword deck (text)");
}

TEST(DeckTruncated, DefinitionWithoutCardsIsAnError) {
  TempDir t;
  const auto p = t.write("cut.k", std::string(kCube) + "*MAT_ELASTIC\n1,1,1,0.3\n*SECTION_SHELL\n");
  EXPECT_EQ(errorOf([&] { crumple::model::readModel(p); }),
            p.string() + ":20: *SECTION_SHELL has no data cards (is the file cut short?)");
}

TEST(DeckCase, KeywordsInCaseBlocksAreSkippedAndReported) {
  TempDir t;
  const auto p =
      t.write("d.k", std::string(kCube) +
                         "*MAT_ELASTIC\n1,1,1,0.3\n"
                         "*TITLE\nbase\n*TITLE CID=1\ncase one\n"
                         "*CASE\n101 LOW\n"
                         "*CASE_BEGIN_1\n*INITIAL_VELOCITY_NODE\n1,5,0,0\n*CASE_END_1\n");
  const auto m = crumple::model::readModel(p);
  EXPECT_EQ(m.title, "base");
  EXPECT_DOUBLE_EQ(m.initial_velocity[0][0], 0.0);
  ASSERT_EQ(m.unsupported.size(), 3u);
  EXPECT_EQ(m.unsupported[0].keyword, "*TITLE");
  EXPECT_EQ(m.unsupported[0].reason,
            "inside *CASE block (CID=1): Crumple runs the deck without load cases");
  // The base deck is what runs: nothing of a load case changes its answer.
  for (const auto& u : m.unsupported) EXPECT_FALSE(u.changes_answer) << u.keyword;
  EXPECT_EQ(m.unsupported[1].keyword, "*CASE");
  EXPECT_EQ(m.unsupported[2].keyword, "*INITIAL_VELOCITY_NODE");
  EXPECT_EQ(m.unsupported[2].first.line, 27);
}

TEST(DeckCard, CursorReadsTypedFieldsAndReportsUnusedValues) {
  using namespace crumple::deck;
  auto [deck, kw] =
      OneKeyword("*CONTROL_SOLID", {{"         1         0         0         2", 0, 5}});
  kw.line = 4;
  CardCursor cur(kw, deck);
  const Card& c = cur.read(keywordSpec("*CONTROL_SOLID").card("card 1"));
  EXPECT_EQ(c.integer("NIPTETS"), 4);  // 0 -> default 4
  const auto unused = cur.flush();
  ASSERT_EQ(unused.size(), 2u);  // ESORT 1 and SWLOCL 2 differ from their defaults
  EXPECT_EQ(unused[0].field, "ESORT");
  EXPECT_EQ(unused[1].field, "SWLOCL");
  EXPECT_EQ(unused[1].where.str(), "x.k:5");
  EXPECT_TRUE(cur.atEnd());
  EXPECT_EQ(errorOf([&] { cur.read(keywordSpec("*CONTROL_SOLID").card("card 2")); }),
            "x.k:4: *CONTROL_SOLID card 2 is missing");
}

TEST(DeckCard, ValuesOutOfColumnsAreReadAsSpaceSeparatedFields) {
  using namespace crumple::deck;
  // v41_ep_4p0uj.k (laser ablation): a script wrote 8-wide columns into this 10-wide card.
  auto [deck, kw] =
      OneKeyword("*BOUNDARY_SPC_NODE",
                 {{"       1       0       1       0       1       0       0       0", 0, 2},
                  {"2\t0\t0\t1", 0, 3},
                  {"         3         0         1         1", 0, 4},
                  {"      82       0       1       0       1       0       0       0", 0, 5}});
  const CardSpec& spec = keywordSpec("*BOUNDARY_SPC").card("card 1");
  CardCursor cur(kw, deck);
  const std::vector<std::array<int64_t, 5>> expected{
      {1, 0, 1, 0, 1}, {2, 0, 0, 1, 0}, {3, 0, 1, 1, 0}, {82, 0, 1, 0, 1}};
  for (const auto& e : expected) {
    const Card& c = cur.read(spec);
    EXPECT_EQ(c.readAsSpaceSeparated(), e[0] != 3) << e[0];
    EXPECT_EQ((std::array<int64_t, 5>{c.integer("NID"), c.integer("CID"), c.integer("DOFX"),
                                      c.integer("DOFY"), c.integer("DOFZ")}),
              e);
  }
  const auto notes = cur.takeNotes();
  ASSERT_EQ(notes.size(), 1u);  // once per keyword
  EXPECT_EQ(notes[0].keyword, "*BOUNDARY_SPC_NODE");
  EXPECT_EQ(notes[0].where.str(), "x.k:2");
  // More values than fields, or one that is not of its field's type: the columns stand, and
  // so does their error.
  kw.lines = {{"1 0 1 0 1 0 0 0 9", 0, 6}, {"1 x\t1", 0, 7}};
  CardCursor again(kw, deck);
  EXPECT_EQ(errorOf([&] { again.read(spec); }),
            "x.k:6: *BOUNDARY_SPC_NODE card 1 field 1 (NID): '1 0 1 0 1' is not an integer");
  EXPECT_EQ(errorOf([&] { again.read(spec); }),
            "x.k:7: *BOUNDARY_SPC_NODE card 1 field 1 (NID): '1 x\t1' is not an integer");
  EXPECT_TRUE(again.takeNotes().empty());
}

namespace {

// Everything a card read from `text` shows, field by field (blank, the value's bits or its
// message, the text), the unused values and whether it was read space-separated; or the
// message the reading throws.
std::string cardReading(const crumple::deck::CardSpec& spec, const crumple::deck::Keyword& kw,
                        const crumple::deck::Deck& deck, const crumple::deck::DataLine& line,
                        crumple::deck::Card::Reading reading) {
  using crumple::deck::Card;
  using crumple::deck::FieldType;
  std::string out;
  const auto attempt = [&out](auto&& f) {
    try {
      out += f();
    } catch (const std::exception& e) {
      out += std::string("! ") + e.what();
    }
    out += "|";
  };
  attempt([&] {
    const Card fresh(spec, &line, kw, deck, reading);
    std::string u = fresh.readAsSpaceSeparated() ? "spaced " : "";
    for (const auto& v : fresh.unusedValues()) u += v.field + "=" + v.value + " ";
    return u + (fresh.allBlank() ? "all blank" : "");
  });
  try {
    const Card c(spec, &line, kw, deck, reading);
    for (const auto& f : spec.fields) {
      attempt([&] { return std::string(c.blank(f.name) ? "blank " : "") + c.text(f.name); });
      if (f.type == FieldType::Text) continue;
      attempt([&] { return std::to_string(std::bit_cast<uint64_t>(c.real(f.name))); });
      attempt([&] { return std::to_string(c.integer(f.name)); });
    }
  } catch (const std::exception& e) {
    out += std::string("! ") + e.what();
  }
  return out;
}

// A field's text as decks write it, well or badly.
std::string randomValue(std::mt19937_64& rng) {
  // Odd values, '|' between them: signs, Fortran and D exponents, blanks, tabs and commas inside,
  // parameters, too many digits, leading zeros.
  static constexpr std::string_view kOdd =
      "|-|.|+5|1.5-3|2.0D0|1e400|abc|1 2|\t7|3\t|4,5|&p|-&p|&p*2|&q|1e|1.e5|-0|-0.0|0.5|12.|1E+2|"
      "7.85e-6|9007199254740993|1234567890123456789|-12345678901234567|x1|1.0|00000012";
  std::uniform_int_distribution<int> kind(0, 6), digits(1, 9), small(0, 999999);
  switch (kind(rng)) {
    case 0:
      return "";
    case 1:
      return std::to_string(small(rng));
    case 2:
      return "-" + std::to_string(small(rng));
    case 3: {
      std::uniform_real_distribution<double> x(-1e3, 1e3);
      return fmt::format("{:.{}g}", x(rng), digits(rng));
    }
    case 4: {
      std::uniform_real_distribution<double> x(-1.0, 1.0);
      return fmt::format("{:.6E}", x(rng) * std::pow(10.0, digits(rng) - 5));
    }
    case 6:  // ids of eight digits, as large models number them
      return std::to_string(std::uniform_int_distribution<int>(0, 99999999)(rng));
    default: {
      std::vector<std::string_view> odd;
      for (std::size_t at = 0, bar = 0; bar != std::string_view::npos; at = bar + 1) {
        bar = kOdd.find('|', at);
        odd.push_back(kOdd.substr(at, bar == std::string_view::npos ? bar : bar - at));
      }
      return std::string(odd[std::uniform_int_distribution<std::size_t>(0, odd.size() - 1)(rng)]);
    }
  }
}

// A line in the card's columns (values right-aligned, or left-aligned, sometimes spilling over
// their width), sometimes cut short or followed by more text.
std::string randomLine(std::mt19937_64& rng, const crumple::deck::CardSpec& spec, int widen) {
  std::uniform_int_distribution<int> pick(0, 9);
  std::string line;
  for (const auto& f : spec.fields) {
    const auto w = static_cast<std::size_t>(std::max(f.width, widen));
    std::string v = f.type == crumple::deck::FieldType::Text && pick(rng) < 5
                        ? std::string(pick(rng) < 2 ? "a,b" : "Name 1")
                        : randomValue(rng);
    if (pick(rng) == 0) v += "  ";  // left of its columns' end
    const std::size_t pad = v.size() < w ? w - v.size() : 0;
    line += pick(rng) == 0 ? v + std::string(pad, ' ') : std::string(pad, ' ') + v;
  }
  if (pick(rng) == 0) line.resize(std::uniform_int_distribution<std::size_t>(0, line.size())(rng));
  if (pick(rng) == 0) line += pick(rng) < 5 ? "   tail" : " , 1";
  return line;
}

}  // namespace

// The one-pass reading of plain lines in compiled columns (Card::readColumns) gives every value,
// text, unused value and message the general reading gives, on random lines of plain and
// malformed fields in each format.
TEST(DeckCard, ColumnReadingMatchesTheGeneralReadingBitForBit) {
  using namespace crumple::deck;
  Deck deck;
  deck.files = {"x.k"};
  deck.parameters["P"] = {"p", 'R', 2.5, "2.5", {}};
  std::mt19937_64 rng(1919);
  const std::vector<std::pair<std::string_view, std::string_view>> cards{
      {"*NODE", "card 1"},
      {"*ELEMENT_SOLID", "card 1"},
      {"*ELEMENT_SHELL", "thickness card"},
      {"*SECTION_SOLID", "card 1"},
      {"*SET_NODE_LIST", "card 1"},
      {"*CONTROL_TERMINATION", "card 1"},
      {"*PARAMETER", "card 1"},
      {"*INCLUDE", "card 1"},
      {"*CONTROL_SOLID", "card 1"},
      {"*SECTION_SHELL", "card 1"},
      {"*PART", "card 1"}};
  int plain_lines = 0, lines = 0;
  for (const auto& [name, label] : cards) {
    const CardSpec& spec = keywordSpec(name).card(label);
    for (const auto& [format, widen] :
         {std::pair{Format::Standard, 0}, {Format::I10, 10}, {Format::Long, 20}}) {
      Keyword kw;
      kw.name = std::string(name);
      kw.format = format;
      kw.line = 1;
      for (int k = 0; k < 400; ++k) {
        const std::string text = randomLine(rng, spec, widen);
        const DataLine line{text, 0, k + 2};
        const std::string general = cardReading(spec, kw, deck, line, Card::Reading::General);
        EXPECT_EQ(cardReading(spec, kw, deck, line, Card::Reading::Columns), general)
            << name << " " << label << " line '" << text << "'";
        ++lines;
        plain_lines += general.find('!') == std::string::npos &&
                       text.find_first_of(",\t&") == std::string::npos;
      }
    }
  }
  // Both kinds are many: plain lines (the one-pass reading) and lines with messages.
  EXPECT_GT(plain_lines, lines / 10);
  EXPECT_LT(plain_lines, lines);
}

namespace {

// The keyword text of `blocks` list keywords of random lines over `layouts` (keyword, card), in
// standard, I10 ('%') and long ('+', and after *KEYWORD LONG=Y) format, with comment and blank
// lines between the records.
std::string randomListDeck(
    std::mt19937_64& rng, const std::vector<std::pair<std::string_view, std::string_view>>& layouts,
    int blocks) {
  using namespace crumple::deck;
  std::uniform_int_distribution<int> pick(0, 9);
  std::string deck = "*KEYWORD\n", long_part = "*KEYWORD LONG=Y\n";
  for (int b = 0; b < blocks; ++b) {
    const auto& [name, label] = layouts[static_cast<std::size_t>(b) % layouts.size()];
    const int format = b / static_cast<int>(layouts.size()) % 4;  // standard, I10, '+', LONG=Y
    std::string& out = format == 3 ? long_part : deck;
    out += std::string(name) + (format == 1 ? " %" : format == 2 ? " +" : "") + "\n";
    for (int k = 0; k < 60; ++k) {
      if (pick(rng) == 0) out += pick(rng) < 5 ? "$ a comment\n" : "   $ indented comment\n";
      if (pick(rng) == 0) out += "\n";
      out += randomLine(rng, keywordSpec(name).card(label), format == 1 ? 10 : format > 1 ? 20 : 0);
      out += "\n";
    }
  }
  return deck + long_part;
}

}  // namespace

// A list keyword's line read without a card (PlainRecord) is read only when the card would
// read it without a message, and then to the same bits: random lines of plain and malformed
// fields (parameters, commas, tabs, blanks, cut short, too many digits) in every format, comment
// lines between records.
TEST(DeckCard, PlainRecordsReadAsTheCardReads) {
  using namespace crumple::deck;
  std::mt19937_64 rng(2019);
  const std::vector<std::pair<std::string_view, std::string_view>> layouts{
      {"*NODE", "card 1"},          {"*ELEMENT_SOLID", "card 1"},
      {"*ELEMENT_SHELL", "card 1"}, {"*ELEMENT_SHELL", "thickness card"},
      {"*ELEMENT_BEAM", "card 1"},  {"*CONTROL_SOLID", "card 1"},
      {"*SECTION_SHELL", "card 1"}, {"*PART", "card 2"},
      {"*PART", "card 1"}};  // a text field: read by the card only
  const std::string text = randomListDeck(rng, layouts, 72);
  Deck deck = memoryDeck(text);
  deck.parameters["P"] = {"p", 'R', 2.5, "2.5", {}};
  ASSERT_EQ(deck.keywords.size(), 72u);
  int plain = 0, lines = 0;
  for (std::size_t k = 0; k < deck.keywords.size(); ++k) {
    const Keyword& kw = deck.keywords[k];
    const CardSpec& spec = keywordSpec(kw.name).card(layouts[k % layouts.size()].second);
    PlainRecord record(spec, kw.format);
    for (const DataLine& line : kw.lines) {
      ++lines;
      std::string general, fast;
      try {
        const Card c(spec, &line, kw, deck, Card::Reading::General);
        for (std::size_t i = 0; i < spec.fields.size(); ++i) {
          const FieldSlot f = spec.slot(spec.fields[i].name);
          general += std::to_string(std::bit_cast<uint64_t>(c.real(f))) + " ";
          if (spec.fields[i].type == FieldType::Int) general += std::to_string(c.integer(f)) + " ";
        }
        general += c.readAsSpaceSeparated() ? "spaced" : "";
      } catch (const std::exception& e) {
        general = std::string("! ") + e.what();
      }
      if (!record.read(line.text)) continue;
      ++plain;
      for (std::size_t i = 0; i < spec.fields.size(); ++i) {
        const FieldSlot f = spec.slot(spec.fields[i].name);
        fast += std::to_string(std::bit_cast<uint64_t>(record.real(f))) + " ";
        if (spec.fields[i].type == FieldType::Int) fast += std::to_string(record.integer(f)) + " ";
      }
      EXPECT_EQ(fast, general) << kw.name << " line " << line.line << " '" << line.text << "'";
    }
  }
  // Both kinds are many: lines read without a card and lines left to it.
  EXPECT_GT(plain, lines / 10);
  EXPECT_LT(plain, lines / 2);
  // A slot of another layout, or the integer of a real field, is a coding error.
  const PlainRecord node(keywordSpec("*NODE").card("card 1"), Format::Standard);
  EXPECT_THROW((void)node.integer(keywordSpec("*NODE").card("card 1").slot("X")), std::logic_error);
  EXPECT_THROW((void)node.real(keywordSpec("*ELEMENT_SOLID").card("card 1").slot("EID")),
               std::logic_error);
}

// *NODE and *ELEMENT_SOLID build the same model, errors and notes (bit for bit, message for
// message) whether their lines are read without cards or all with them (a tab at the end of
// each line sends it to the card's general reading, and changes no value).
TEST(DeckCard, ListKeywordsBuildAsWithCardsOnly) {
  std::mt19937_64 rng(1920);
  std::uniform_int_distribution<int> pick(0, 19), rare(0, 199), node(201, 400), any(1, 420);
  const auto field = [&](int width, const std::string& v) {
    return std::string(static_cast<std::size_t>(std::max(0, width - static_cast<int>(v.size()))),
                       ' ') +
           v;
  };
  const auto odd = [&](const std::string& v) {
    switch (rare(rng)) {
      case 0:
        return std::string("x");
      case 1:
        return std::string("");
      case 2:
        return "-" + v;
      case 3:
        return v + ".5";
      case 4:
        return std::string("&p");
      case 5:
        return std::string("8");
      default:
        return v;
    }
  };
  const auto coordinate = [&] {
    return fmt::format("{:.{}g}", std::uniform_real_distribution<double>(-1e3, 1e3)(rng),
                       1 + pick(rng) % 12);
  };
  // Nodes 201..400 plainly written; 1..200 in short keywords (an error ends its keyword's
  // reading) with odd values; elements mostly on the former.
  std::string nodes = "*NODE\n", solids;
  for (int id = 201; id <= 400; ++id)
    nodes += field(8, std::to_string(id)) + field(16, coordinate()) + field(16, coordinate()) +
             field(16, coordinate()) + "\n";
  for (int b = 0; b < 100; ++b) {
    nodes += b % 3 == 0 ? "*NODE %\n" : "*NODE\n";
    const int w = b % 3 == 0 ? 10 : 8;
    for (int k = 0; k < 2; ++k) {
      const int id = b * 2 + k + 1;
      nodes += field(w, odd(std::to_string(rare(rng) == 0 ? id - 1 : id)));
      for (int c = 0; c < 3; ++c) nodes += field(16, odd(coordinate()));
      if (pick(rng) < 8) nodes += field(w, odd(std::to_string(pick(rng) % 8)));
      if (pick(rng) < 3) nodes += field(w, odd(std::to_string(pick(rng) % 8)));
      nodes += pick(rng) == 0 ? "\n$ comment\n" : "\n";
    }
    solids += "*ELEMENT_SOLID\n";
    for (int k = 0; k < 2; ++k) {
      solids += field(8, odd(std::to_string(b * 2 + k + 1)));
      const int part = pick(rng);
      solids += field(8, odd(part < 14 ? "1" : part < 18 ? "2" : "3"));
      std::array<int, 8> n{};
      for (int& i : n) i = pick(rng) == 0 ? any(rng) : node(rng);
      if (pick(rng) < 4) n[5] = n[4], n[7] = n[6];          // a pentahedron
      if (pick(rng) < 8) n[7] = n[6] = n[5] = n[4] = n[3];  // N4 repeated
      const int given = pick(rng) < 3 ? 4 : 8;              // N1..N4 alone
      for (int i = 0; i < given; ++i) solids += field(8, odd(std::to_string(n[i])));
      solids += pick(rng) == 0 ? "\n\n" : "\n";
    }
  }
  const auto tabbed = [](const std::string& text) {
    std::string out;
    for (std::size_t at = 0, nl; at < text.size(); at = nl + 1) {
      nl = text.find('\n', at);
      const std::string line = text.substr(at, nl - at);
      out += line + (line.empty() || line[0] == '*' || line[0] == '$' ? "" : "\t") + "\n";
    }
    return out;
  };
  const auto built = [](const std::string& text, bool collect) {
    std::string out;
    try {
      crumple::model::ReadOptions options;
      options.collect_errors = collect;
      options.allow_unsupported = collect;
      crumple::deck::Deck deck = memoryDeck(text);
      deck.parameters["P"] = {"p", 'R', 2.5, "2.5", {}};
      const auto m = crumple::model::buildModel(deck, "main.k", options);
      for (std::size_t i = 0; i < m.nodes.size(); ++i)
        out += fmt::format(
            "node {} {} {} {}\n", m.nodes.id[i], std::bit_cast<uint64_t>(m.nodes.x[i][0]),
            std::bit_cast<uint64_t>(m.nodes.x[i][1]), std::bit_cast<uint64_t>(m.nodes.x[i][2]));
      for (std::size_t e = 0; e < m.solids.size(); ++e) {
        out += fmt::format("solid {} {}", m.solids.id[e], m.solids.part[e]);
        for (const int32_t n : m.solids.nodes[e]) out += " " + std::to_string(n);
        out += "\n";
      }
      for (const auto& e : m.errors) out += "error " + e.message + "\n";
      for (const auto& i : m.ignored)
        out += "ignored " + i.where.str() + " " + i.keyword + " " + i.field + " " + i.reason + "\n";
    } catch (const std::exception& e) {
      out += std::string("! ") + e.what();
    }
    return out;
  };
  // Each solid form: hexahedra (1, 2), tetrahedra (10, 13); part 2 pentahedra (15), part 3
  // a shell section (refused for solids).
  for (const int elform : {1, 2, 10, 13}) {
    const std::string text = fmt::format(R"(*KEYWORD
*MAT_ELASTIC
1,7.8e-9,210000,0.3
*SECTION_SOLID
1,{}
*SECTION_SOLID
2,15
*SECTION_SHELL
3
0.01
*PART
one
1,1,1
*PART
two
2,2,1
*PART
three
3,3,1
)",
                                         elform) +
                             nodes + solids;
    for (const bool collect : {true, false}) {
      const std::string with_cards = built(tabbed(text), collect);
      EXPECT_EQ(built(text, collect), with_cards) << elform;
      if (!collect) continue;
      const auto count = [&](std::string_view what) {
        std::size_t n = 0;
        for (std::size_t at = with_cards.find(what); at != std::string::npos;
             at = with_cards.find(what, at + 1))
          ++n;
        return n;
      };
      // Messages are compared too, and solids of every part's reading.
      EXPECT_GT(count("\nerror "), 20u) << elform;
      EXPECT_GT(count("\nsolid "), 30u) << elform;
    }
  }
}

// A field slot reads the field it names, and only on a card of its own layout.
TEST(DeckCard, FieldSlotsReadTheirFieldOfTheirLayoutOnly) {
  using namespace crumple::deck;
  auto [deck, kw] = OneKeyword(
      "*NODE", {{"       7             1.5            -2.5          3.0e+1       1", 0, 2}});
  const CardSpec& spec = keywordSpec("*NODE").card("card 1");
  const FieldSlot nid = spec.slot("NID"), z = spec.slot("Z"), rc = spec.slot("RC");
  EXPECT_EQ(nid.index, 0u);
  EXPECT_EQ(z.name, "Z");
  CardCursor cur(kw, deck);
  const Card& c = cur.read(spec);
  EXPECT_EQ(c.integer(nid), 7);
  EXPECT_EQ(c.real(z), 30.0);
  EXPECT_FALSE(c.blank(z));
  EXPECT_TRUE(c.blank(rc));
  EXPECT_EQ(c.integer(rc), 0);
  EXPECT_THROW((void)spec.slot("N1"), std::logic_error);
  const FieldSlot other = keywordSpec("*ELEMENT_SOLID").card("card 1").slot("EID");
  EXPECT_THROW((void)c.integer(other), std::logic_error);
  // *NODE TC read through its slot keeps the message of the name.
  kw.lines = {{"       8               0               0               0       9", 0, 3}};
  CardCursor again(kw, deck);
  EXPECT_EQ(errorOf([&] {
              const Card& d = again.read(spec);
              const FieldSlot tc = spec.slot("TC");
              if (d.integer(tc) > 7) d.fail(tc.name, "must be 0 to 7");
            }),
            "x.k:3: *NODE card 1 field 5 (TC): must be 0 to 7");
}
