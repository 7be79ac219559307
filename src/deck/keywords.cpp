// Card layouts of every keyword Crumple reads, transcribed from the LS-DYNA Keyword User's
// Manual, Vol. I (R10-R14), one entry per keyword, in the manual's field order. Defaults are
// the manual's; kZeroIsDefault marks fields where the manual says 0 selects the default.
// kQuiet marks fields without influence on the solution, which are never reported as ignored.
#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

#include "deck/layout.hpp"

namespace crumple::deck {

namespace {

constexpr uint8_t Z = kZeroIsDefault;
constexpr uint8_t Q = kQuiet;
using Pairs = std::initializer_list<std::pair<std::string_view, std::string_view>>;

// Heading line of the _ID option of boundary conditions and rigid walls: ID (I10), HEADING (A70).
CardSpec idCard() {
  return {"id card", {I("ID"), A("HEADING", 70)}};
}
// Card 1 shared by the *SET_ keywords: SID DA1..DA4 SOLVER.
CardSpec setCard() {
  return {"card 1",
          {I("SID"), R("DA1", 0, Q), R("DA2", 0, Q), R("DA3", 0, Q), R("DA4", 0, Q),
           A("SOLVER", 10, "MECH", Q), A("ITS", 10, {}, Q)}};
}
// Eight ids per card (I10), named PREFIX1..PREFIX8.
CardSpec idList(std::string_view label, std::string_view n1, std::string_view n2,
                std::string_view n3, std::string_view n4, std::string_view n5, std::string_view n6,
                std::string_view n7, std::string_view n8) {
  return {label, {I(n1), I(n2), I(n3), I(n4), I(n5), I(n6), I(n7), I(n8)}};
}
CardSpec rangeCard() {
  return {"range card", {I("B1"), I("E1"), I("B2"), I("E2"), I("B3"), I("E3"), I("B4"), I("E4")}};
}
// *DATABASE_<ascii file> (GLSTAT, MATSUM, NODOUT, RWFORC, ...): DT BINARY LCUR IOOPT.
std::vector<CardSpec> asciiDatabase() {
  return {{"card 1", {R("DT"), I("BINARY", 0, Q), I("LCUR"), I("IOOPT", 0, Q)}}};
}

std::vector<KeywordSpec> makeTables() {
  std::vector<KeywordSpec> t;
  // ---- reader-level keywords (src/deck/deck.cpp) --------------------------------------------
  t.push_back({"*PARAMETER",
               {{"card 1",
                 {A("PRMR1"), A("VAL1"), A("PRMR2"), A("VAL2"), A("PRMR3"), A("VAL3"), A("PRMR4"),
                  A("VAL4")}}}});
  t.push_back({"*PARAMETER_EXPRESSION", {{"card 1", {A("PRMR"), A("EXPRESSION", 70)}}}});
  t.push_back({"*PARAMETER_DUPLICATION", {{"card 1", {I("DFLAG", 1, Z)}}}});
  t.push_back({"*INCLUDE", {{"card 1", {A("FILENAME", 80)}}}});
  t.push_back({"*INCLUDE_PATH", {{"card 1", {A("PATH", 80)}}}});
  // ---- general --------------------------------------------------------------------------------
  t.push_back({"*TITLE", {titleCard("card 1")}});
  // ---- mesh: *NODE I8,3E16,2I8 and *ELEMENT_SOLID 10I8 (the manual's narrow formats) ---------
  t.push_back({"*NODE",
               {{"card 1",
                 {I("NID", 0, 0, 8), R("X", 0, 0, 16), R("Y", 0, 0, 16), R("Z", 0, 0, 16),
                  I("TC", 0, 0, 8), I("RC", 0, 0, 8)}}}});
  t.push_back({"*ELEMENT_SOLID",
               {{"card 1",
                 {I("EID", 0, 0, 8), I("PID", 0, 0, 8), I("N1", 0, 0, 8), I("N2", 0, 0, 8),
                  I("N3", 0, 0, 8), I("N4", 0, 0, 8), I("N5", 0, 0, 8), I("N6", 0, 0, 8),
                  I("N7", 0, 0, 8), I("N8", 0, 0, 8)}},
                // Two-card form written by most pre-processors ("ten node format").
                {"card 2",
                 {I("N1", 0, 0, 8), I("N2", 0, 0, 8), I("N3", 0, 0, 8), I("N4", 0, 0, 8),
                  I("N5", 0, 0, 8), I("N6", 0, 0, 8), I("N7", 0, 0, 8), I("N8", 0, 0, 8),
                  I("N9", 0, 0, 8), I("N10", 0, 0, 8)}}}});
  // *ELEMENT_TSHELL 10I8: EID PID N1..N8, N1-N4 the bottom face, N5-N8 the top (Keyword Manual).
  t.push_back({"*ELEMENT_TSHELL",
               {{"card 1",
                 {I("EID", 0, 0, 8), I("PID", 0, 0, 8), I("N1", 0, 0, 8), I("N2", 0, 0, 8),
                  I("N3", 0, 0, 8), I("N4", 0, 0, 8), I("N5", 0, 0, 8), I("N6", 0, 0, 8),
                  I("N7", 0, 0, 8), I("N8", 0, 0, 8)}}}});
  // *ELEMENT_MASS I8,I8,E16,I8 (Keyword Manual, *ELEMENT_MASS).
  t.push_back({"*ELEMENT_MASS",
               {{"card 1",
                 {I("EID", 0, 0, 8), I("NID", 0, 0, 8), R("MASS", 0, 0, 16), I("PID", 0, 0, 8)}}}});
  // *ELEMENT_SPH I8,I8,E16: NID PID MASS (MASS < 0: the particle's volume, its mass from the
  // part's density; Keyword Manual, *ELEMENT_SPH).
  t.push_back(
      {"*ELEMENT_SPH", {{"card 1", {I("NID", 0, 0, 8), I("PID", 0, 0, 8), R("MASS", 0, 0, 16)}}}});
  // *ELEMENT_SHELL 10I8; _THICKNESS adds THIC1-4 and BETA (E16 each).
  t.push_back({"*ELEMENT_SHELL",
               {{"card 1",
                 {I("EID", 0, 0, 8), I("PID", 0, 0, 8), I("N1", 0, 0, 8), I("N2", 0, 0, 8),
                  I("N3", 0, 0, 8), I("N4", 0, 0, 8), I("N5", 0, 0, 8), I("N6", 0, 0, 8),
                  I("N7", 0, 0, 8), I("N8", 0, 0, 8)}},
                {"thickness card",
                 {R("THIC1", 0, 0, 16), R("THIC2", 0, 0, 16), R("THIC3", 0, 0, 16),
                  R("THIC4", 0, 0, 16), R("BETA", 0, 0, 16)}}}});
  // *ELEMENT_BEAM 10I8: EID PID N1 N2 N3 RT1 RR1 RT2 RR2 LOCAL.
  t.push_back({"*ELEMENT_BEAM",
               {{"card 1",
                 {I("EID", 0, 0, 8), I("PID", 0, 0, 8), I("N1", 0, 0, 8), I("N2", 0, 0, 8),
                  I("N3", 0, 0, 8), I("RT1", 0, 0, 8), I("RR1", 0, 0, 8), I("RT2", 0, 0, 8),
                  I("RR2", 0, 0, 8), I("LOCAL", 2, Z, 8)}},
                // _THICKNESS: the section's dimensions per element, 5E16 (by ELFORM: 1 and 9
                // TS1 TS2 TT1 TT2; 2 A ISS ITT IRR SA; 3 A).
                {"thickness card",
                 {R("PARM1", 0, 0, 16), R("PARM2", 0, 0, 16), R("PARM3", 0, 0, 16),
                  R("PARM4", 0, 0, 16), R("PARM5", 0, 0, 16)}}}});
  // *ELEMENT_DISCRETE I8,I8,I8,I8,I8,E16,I8,E16.
  t.push_back({"*ELEMENT_DISCRETE",
               {{"card 1",
                 {I("EID", 0, 0, 8), I("PID", 0, 0, 8), I("N1", 0, 0, 8), I("N2", 0, 0, 8),
                  I("VID", 0, 0, 8), R("S", 1, Z, 16), I("PF", 0, 0, 8), R("OFFSET", 0, 0, 16)}}}});
  // ---- parts, sections, materials -----------------------------------------------------------
  // *PART; _INERTIA adds cards 3-5 (and card 6 for IRCS=1) after card 2 of each part.
  // *PART_COMPOSITE: a heading, card 2, then ply cards of two plies each (Keyword Manual vol. I).
  t.push_back({"*PART_COMPOSITE",
               {{"card 1", {A("HEADING", 70)}},
                {"card 2",
                 {I("PID"), I("ELFORM", 2, Z), R("SHRF", 1, Z), R("NLOC"), R("MAREA"), I("HGID"),
                  I("ADPOPT"), I("ITHELFM")}},
                {"ply card",
                 {I("MID1"), R("THICK1"), R("B1"), I("TMID1"), I("MID2"), R("THICK2"), R("B2"),
                  I("TMID2")}}}});
  t.push_back(
      {"*PART",
       {{"card 1", {A("HEADING", 70)}},
        {"card 2",
         {I("PID"), I("SECID"), I("MID"), I("EOSID"), I("HGID"), I("GRAV"), I("ADPOPT"),
          I("TMID")}},
        {"contact card",
         {R("FS"), R("FD"), R("DC"), R("VC"), R("OPTT"), R("SFT"), R("SSF", 1, Z), R("CPARM8")}},
        {"inertia card 3", {R("XC"), R("YC"), R("ZC"), R("TM"), I("IRCS"), I("NODEID")}},
        {"inertia card 4", {R("IXX"), R("IXY"), R("IXZ"), R("IYY"), R("IYZ"), R("IZZ")}},
        {"inertia card 5", {R("VTX"), R("VTY"), R("VTZ"), R("VRX"), R("VRY"), R("VRZ")}},
        {"inertia card 6",
         {R("XL"), R("YL"), R("ZL"), R("XLIP"), R("YLIP"), R("ZLIP"), I("CID")}}}});
  t.push_back({"*SECTION_SOLID",
               {titleCard(),
                {"card 1",
                 {I("SECID"), I("ELFORM", 1), I("AET"), A("UNUSED1", 10, {}, Q),
                  A("UNUSED2", 10, {}, Q), A("UNUSED3", 10, {}, Q), R("COHOFF"), R("GASKETT")}}}});
  // *SECTION_SPH: SECID CSLH HMIN HMAX SPHINI DEATH START SPHKERN (Keyword Manual vol. I).
  t.push_back({"*SECTION_SPH",
               {titleCard(),
                {"card 1",
                 {I("SECID"), R("CSLH", 1.2, Z), R("HMIN", 0.2, Z), R("HMAX", 2.0, Z), R("SPHINI"),
                  R("DEATH", 1e20, Z), R("START"), I("SPHKERN")}}}});
  t.push_back(
      {"*SECTION_SHELL",
       {titleCard(),
        {"card 1",
         {I("SECID"), I("ELFORM", 2, Z), R("SHRF", 1, Z), I("NIP", 2, Z), R("PROPT", 1, Z),
          I("QR/IRID"), I("ICOMP"), I("SETYP", 1, Z)}},
        {"card 2",
         {R("T1"), R("T2"), R("T3"), R("T4"), R("NLOC"), R("MAREA"), I("IDOF"), I("EDGSET")}},
        // ICOMP = 1: the material angle of each integration point, 8 a card (NIP of them).
        {"angle card", {R("B1"), R("B2"), R("B3"), R("B4"), R("B5"), R("B6"), R("B7"), R("B8")}}}});
  // *SECTION_TSHELL (Keyword Manual vol. I): card 2 holds the ICOMP = 1 layer angles.
  t.push_back(
      {"*SECTION_TSHELL",
       {titleCard(),
        {"card 1",
         {I("SECID"), I("ELFORM", 1, Z), R("SHRF", 1, Z), I("NIP", 2, Z), R("PROPT", 1, Z), I("QR"),
          I("ICOMP"), I("TSHEAR")}},
        {"angle card", {R("B1"), R("B2"), R("B3"), R("B4"), R("B5"), R("B6"), R("B7"), R("B8")}}}});
  t.push_back(
      {"*SECTION_BEAM",
       {titleCard(),
        {"card 1",
         {I("SECID"), I("ELFORM", 1, Z), R("SHRF", 1, Z), I("QR/IRID", 2, Z), I("CST"), R("SCOOR"),
          R("NSM"), R("NAUPD", 0, Q)}},
        {"integrated card", {R("TS1"), R("TS2"), R("TT1"), R("TT2"), R("NSLOC"), R("NTLOC")}},
        {"resultant card", {R("A"), R("ISS"), R("ITT"), R("J"), R("SA"), R("IST")}}}});
  // *INTEGRATION_BEAM (Keyword Manual vol. I): card 2 for a standard shape (ICST > 0), a
  // point card per user point (NIP).
  t.push_back(
      {"*INTEGRATION_BEAM",
       {{"card 1", {I("IRID"), I("NIP"), R("RA"), I("ICST"), I("K")}},
        {"card 2", {R("D1"), R("D2"), R("D3"), R("D4"), R("D5"), R("D6"), R("SREF"), R("TREF")}},
        {"point card", {R("S"), R("T"), R("WF"), I("PID")}}}});
  // *INTEGRATION_SHELL (Keyword Manual vol. I): a point card per point (NIPTS).
  t.push_back({"*INTEGRATION_SHELL",
               {{"card 1", {I("IRID"), I("NIPTS"), I("ESOP"), I("FAILOPT")}},
                {"point card", {R("S"), R("WF"), I("PID")}}}});
  t.push_back({"*SECTION_DISCRETE",
               {titleCard(),
                {"card 1", {I("SECID"), I("DRO"), R("KD"), R("V0"), R("CL"), R("FD")}},
                {"card 2", {R("CDL"), R("TDL")}}}});
  t.push_back({"*HOURGLASS",
               {titleCard(),
                {"card 1",
                 {I("HGID"), I("IHQ", 1, Z), R("QM", 0.1, Z), I("IBQ"), R("Q1", 1.5, Z),
                  R("Q2", 0.06, Z), R("QB"), R("QW")}}}});
  // *EOS_LINEAR_POLYNOMIAL (*EOS_001) and *EOS_GRUNEISEN (*EOS_004): Keyword Manual vol. II,
  // "*EOS". V0, the initial relative volume, is 1 when blank or 0.
  t.push_back(
      {"*EOS_LINEAR_POLYNOMIAL",
       {titleCard(),
        {"card 1", {I("EOSID"), R("C0"), R("C1"), R("C2"), R("C3"), R("C4"), R("C5"), R("C6")}},
        {"card 2", {R("E0"), R("V0", 1, Z)}}}});
  t.push_back(
      {"*EOS_GRUNEISEN",
       {titleCard(),
        {"card 1", {I("EOSID"), R("C"), R("S1"), R("S2"), R("S3"), R("GAMAO"), R("A"), R("E0")}},
        {"card 2", {R("V0", 1, Z)}}}});
  // *EOS_TABULATED_COMPACTION (*EOS_008) and *EOS_TABULATED (*EOS_009): Keyword Manual vol.
  // II, "*EOS". Card 1 (width 10) then the table, five fields of width 16 a card: EV1-10
  // (ln V), C1-10, T1-10 and, for compaction, K1-10. LCC, LCT, LCK (curves in place of the
  // table) and LCID (energy deposition) of newer manuals are read to be refused when set.
  {
    static constexpr std::string_view kTable[4][10] = {
        {"EV1", "EV2", "EV3", "EV4", "EV5", "EV6", "EV7", "EV8", "EV9", "EV10"},
        {"C1", "C2", "C3", "C4", "C5", "C6", "C7", "C8", "C9", "C10"},
        {"T1", "T2", "T3", "T4", "T5", "T6", "T7", "T8", "T9", "T10"},
        {"K1", "K2", "K3", "K4", "K5", "K6", "K7", "K8", "K9", "K10"}};
    const auto row = [](int column, int half) {
      std::vector<FieldSpec> f;
      for (int i = 0; i < 5; ++i) f.push_back(R(kTable[column][5 * half + i], 0, 0, 16));
      return f;
    };
    const auto table = [&](std::string_view name, std::vector<FieldSpec> card1, int columns) {
      KeywordSpec k{name, {titleCard(), {"card 1", std::move(card1)}}};
      static constexpr std::string_view kLabels[8] = {"card 2", "card 3", "card 4", "card 5",
                                                      "card 6", "card 7", "card 8", "card 9"};
      for (int c = 0; c < 2 * columns; ++c) k.cards.push_back({kLabels[c], row(c / 2, c % 2)});
      return k;
    };
    t.push_back(table(
        "*EOS_TABULATED_COMPACTION",
        {I("EOSID"), R("GAMA"), R("E0"), R("V0", 1, Z), I("LCC"), I("LCT"), I("LCK"), I("LCID")},
        4));
    t.push_back(table("*EOS_TABULATED",
                      {I("EOSID"), R("GAMA"), R("E0"), R("V0", 1, Z), I("LCC"), I("LCT")}, 3));
  }
  // *MAT_ADD_EROSION: Keyword Manual vol. II. Cards 3-5 (damage, forming limit, nonlocal and
  // temperature criteria) are read only to refuse what they set (model/build_erosion.cpp).
  t.push_back({"*MAT_ADD_EROSION",
               {titleCard(),
                {"card 1",
                 {I("MID"), R("EXCL"), R("MXPRES"), R("MNEPS"), R("EFFEPS"), R("VOLEPS"),
                  R("NUMFIP", 1), R("NCS", 1)}},
                {"card 2",
                 {R("MNPRES"), R("SIGP1"), R("SIGVM"), R("MXEPS"), R("EPSSH"), R("SIGTH"),
                  R("IMPULSE"), R("FAILTM")}},
                {"card 3",
                 {I("IDAM"), I("DMGTYP"), R("LCSDG"), R("ECRIT"), R("DMGEXP"), R("DCRIT"),
                  R("FADEXP"), I("LCREGD")}},
                {"card 4",
                 {I("LCFLD"), I("NSFF", 10), R("EPSTHIN"), R("ENGCRT"), R("RADCRT"), I("LCEPS12"),
                  I("LCEPS13"), I("LCEPSMX")}},
                {"card 5", {R("DTEFLT"), R("VOLFRAC", 0.5), R("MXTMP"), R("DTMIN")}}}});
  // ---- controls -------------------------------------------------------------------------------
  t.push_back(
      {"*CONTROL_TERMINATION",
       {{"card 1",
         {R("ENDTIM"), I("ENDCYC"), R("DTMIN"), R("ENDENG"), R("ENDMAS", 1e8, Z), I("NOSOL")}}}});
  t.push_back({"*CONTROL_TIMESTEP",
               {{"card 1",
                 {R("DTINIT"), R("TSSFAC", 0.9, Z), I("ISDO"), R("TSLIMT"), R("DT2MS"), I("LCTM"),
                  I("ERODE"), I("MS1ST")}},
                {"card 2",
                 {R("DT2MSF"), I("DT2MSLC"), I("IMSCL"), A("UNUSED1", 10, {}, Q),
                  A("UNUSED2", 10, {}, Q), R("RMSCL"), R("EMSCL"), I("IHDO")}}}});
  t.push_back(
      {"*CONTROL_RIGID",
       {{"card 1",
         {I("LMF"), I("JNTF"), I("ORTHMD"), I("PARTM"), I("SPARSE"), I("METALF"), I("PLOTEL"),
          I("RBSMS")}},
        {"card 2", {I("NORBIC"), R("GJADSTF"), R("GJADVSC"), R("TJADSTF"), R("TJADVSC")}}}});
  t.push_back({"*CONTROL_HOURGLASS", {{"card 1", {I("IHQ", 1, Z), R("QH", 0.1, Z)}}}});
  t.push_back({"*CONTROL_BULK_VISCOSITY",
               {{"card 1", {R("Q1", 1.5, Z), R("Q2", 0.06, Z), I("TYPE", 1, Z), I("BTYPE")}}}});
  t.push_back(
      {"*CONTROL_ENERGY",
       {{"card 1", {I("HGEN", 1, Z), I("RWEN", 2, Z), I("SLNTEN", 1, Z), I("RYLEN", 1, Z)}}}});
  // *CONTROL_SPH (Keyword Manual vol. I): card 1 NCBS BOXID DT IDIM NMNEIGH FORM START MAXV,
  // card 2 CONT DERIV INI ISHOW IEROD ICONT IAVIS ISYMP, card 3 ITHK ISTAB QL - SPHSORT ISHIFT.
  t.push_back({"*CONTROL_SPH",
               {{"card 1",
                 {I("NCBS", 1, Z), I("BOXID"), R("DT", 1e20, Z), I("IDIM"), I("NMNEIGH", 150, Z),
                  I("FORM"), R("START"), R("MAXV", 1e15, Z)}},
                {"card 2",
                 {I("CONT"), I("DERIV"), I("INI"), I("ISHOW", 0, Q), I("IEROD"), I("ICONT"),
                  I("IAVIS"), I("ISYMP", 100, Z)}},
                {"card 3",
                 {I("ITHK"), I("ISTAB"), R("QL", 0.01, Z), I("UNUSED", 0, Q), I("SPHSORT", 0, Q),
                  I("ISHIFT")}}}});
  t.push_back({"*CONTROL_SOLID",
               {{"card 1",
                 {I("ESORT"), I("FMATRX"), I("NIPTETS", 4, Z), I("SWLOCL", 1, Z), I("PSFAIL"),
                  R("T10JTOL"), I("ICOH"), I("TET13K")}},
                {"card 2",
                 {I("PM1", 0, 0, 8), I("PM2", 0, 0, 8), I("PM3", 0, 0, 8), I("PM4", 0, 0, 8),
                  I("PM5", 0, 0, 8), I("PM6", 0, 0, 8), I("PM7", 0, 0, 8), I("PM8", 0, 0, 8),
                  I("PM9", 0, 0, 8), I("PM10", 0, 0, 8)}}}});
  t.push_back({"*CONTROL_ACCURACY",
               {{"card 1", {I("OSU"), I("INN", 1, Z), I("PIDOSU"), I("IACC"), R("EXACC")}}}});
  // Printed-output controls of LS-DYNA itself (d3hsp, messag): no influence on the solution.
  t.push_back({"*CONTROL_OUTPUT",
               {{"card 1",
                 {I("NPOPT", 0, Q), I("NEECHO", 0, Q), I("NREFUP", 0, Q), I("IACCOP", 0, Q),
                  R("OPIFS", 0, Q), I("IPNINT", 0, Q), I("IKEDIT", 0, Q), I("IFLUSH", 0, Q)}}}});
  t.push_back(
      {"*CONTROL_SHELL",
       {{"card 1",
         {R("WRPANG", 20, Z), I("ESORT"), I("IRNXX", -1, Z), I("ISTUPD"), I("THEORY", 2, Z),
          I("BWC", 2, Z), I("MITER", 1, Z), I("PROJ")}},
        {"card 2",
         {R("ROTASCL", 1, Z), I("INTGRD"), I("LAMSHT", 0, Q), I("CSTYP6", 1, Z), I("TSHELL")}}}});
  t.push_back({"*CONTROL_CONTACT",
               {{"card 1",
                 {R("SLSFAC", 0.1, Z), R("RWPNAL"), I("ISLCHK", 1, Z), I("SHLTHK"),
                  I("PENOPT", 1, Z), I("THKCHG"), I("ORIEN", 1, Z), I("ENMASS")}},
                {"card 2",
                 {I("USRSTR"), I("USRFAC"), I("NSBCS"), I("INTERM"), R("XPENE", 4, Z), I("SSTHK"),
                  I("ECDT"), I("TIEDPRJ")}},
                {"card 3",
                 {R("SFRIC"), R("DFRIC"), R("EDC"), R("VFC"), R("TH"), R("TH_SF"), R("PEN_SF"),
                  R("PTSCL")}},
                {"card 4",
                 {I("IGNORE"), I("FRCENG"), I("SKIPRWG"), I("OUTSEG"), I("SPOTSTP"), I("SPOTDEL"),
                  R("SPOTHIN"), I("DIR_TIE")}},
                {"card 5",
                 {I("ISYM"), I("NSEROD"), I("RWGAPS"), R("RWGDTH"), R("RWKSF", 1, Z), I("ICOV"),
                  R("SWRADF"), I("ITHOFF")}}}});
  // *CONTACT_<type>[_ID|_TITLE]: one layout for every type Crumple runs (card A optional).
  t.push_back(
      {"*CONTACT",
       {{"id card", {I("CID"), A("HEADING", 70)}},
        // _MPP: after the id card, before card 1; the second card only when it starts with
        // '&' (Keyword Manual, *CONTACT, MPP cards). Distributed-memory settings: reported.
        {"mpp card 1",
         {I("IGNORE"), I("BCKT", 200, Z), I("LCBCKT"), I("NS2TRK", 3, Z), I("INITITR", 2, Z),
          R("PARMAX", 1.0005, Z), A("UNUSED", 10, {}, Q), I("CPARM8")}},
        {"mpp card 2", {A("AMP", 10, {}, Q), I("CHKSEGS"), R("PENSF", 1, Z), I("GRPABLE")}},
        {"card 1",
         {I("SSID"), I("MSID"), I("SSTYP"), I("MSTYP"), I("SBOXID"), I("MBOXID"), I("SPR"),
          I("MPR")}},
        {"card 2",
         {R("FS"), R("FD"), R("DC"), R("VC"), R("VDC"), I("PENCHK"), R("BT"), R("DT", 1e20, Z)}},
        {"card 3",
         {R("SFS", 1, Z), R("SFM", 1, Z), R("SST"), R("MST"), R("SFST", 1, Z), R("SFMT", 1, Z),
          R("FSF", 1, Z), R("VSF", 1, Z)}},
        // _TIEBREAK: the card after card 3 (Keyword Manual, *CONTACT, tiebreak cards):
        // AUTOMATIC_..._TIEBREAK's failure stresses, TIEBREAK_NODES_TO_SURFACE's forces.
        {"tiebreak card",
         {I("OPTION", 1, Z), R("NFLS"), R("SFLS"), R("PARAM"), R("ERATEN"), R("ERATES"), R("CT2CN"),
          R("CN")}},
        {"tiebreak force card", {R("NFLF"), R("SFLF"), R("NEN", 2, Z), R("MES", 2, Z)}},
        // _ERODING_: the card after card 3 (Keyword Manual, *CONTACT, "additional card for the
        // ERODING option").
        {"eroding card", {I("ISYM"), I("EROSOP"), I("IADJ")}},
        {"card A",
         {I("SOFT"), R("SOFSCL", 0.1, Z), I("LCIDAB"), R("MAXPAR", 1.025, Z), R("SBOPT"),
          I("DEPTH"), I("BSORT"), I("FRCFRQ", 1, Z)}},
        // Optional cards B-D: read so that their non-default values are reported.
        {"card B",
         {R("PENMAX"), I("THKOPT"), I("SHLTHK"), I("SNLOG"), I("ISYM"), I("I2D3D"), R("SLDTHK"),
          R("SLDSTF")}},
        {"card C",
         {I("IGAP"), I("IGNORE"), R("DPRFAC"), R("DTSTIF"), R("EDGEK"), R("UNUSED6"), R("UNUSED7"),
          R("FLANGL")}},
        {"card D",
         {I("Q2TRI"), R("DTPCHK"), R("SFNBR"), R("FNLSCL"), R("DNLSCL"), I("TCSO"), I("TIEDID"),
          I("SHLEDG")}}}});
  t.push_back(
      {"*CONTROL_SOLUTION", {{"card 1", {I("SOLN"), I("NLQ"), I("ISNAN"), I("LCINT", 100, Z)}}}});
  t.push_back(
      {"*CONTROL_UNITS",
       {{"card 1", {A("LENGTH"), A("TIME"), A("MASS"), A("TEMP"), A("VERSION"), A("SI")}}}});
  // Dynamic relaxation (*CONTROL_DAMPING is its name in LS-DYNA 93x-94x decks); the
  // parameters act only when IDRFLG or a curve's SIDR turns it on. EDTTL acts only with
  // IRELAL = 1 (refused).
  for (std::string_view name : {"*CONTROL_DYNAMIC_RELAXATION", "*CONTROL_DAMPING"})
    t.push_back({name,
                 {{"card 1",
                   {I("NRCYCK", 250, Z), R("DRTOL", 0.001, Z), R("DRFCTR", 0.995, Z), R("DRTERM"),
                    R("TSSFDR"), I("IRELAL"), R("EDTTL", 0.04, Z | Q), I("IDRFLG")}}}});
  // IMFLAG 0 explicit, 1 implicit, 2 explicit then implicit springback, < 0 a curve of time.
  t.push_back({"*CONTROL_IMPLICIT_GENERAL",
               {{"card 1",
                 {I("IMFLAG"), R("DT0", 0, Q), I("IMFORM", 2, Q), I("NSBS", 1, Q), I("IGS", 2, Q),
                  I("CNSTN", 0, Q), I("FORM", 0, Q), I("ZERO_V", 0, Q)}}}});
  // ---- database -----------------------------------------------------------------------------
  for (std::string_view name :
       {"*DATABASE_GLSTAT", "*DATABASE_MATSUM", "*DATABASE_NODOUT", "*DATABASE_RWFORC",
        "*DATABASE_RCFORC", "*DATABASE_SLEOUT", "*DATABASE_SECFORC", "*DATABASE_SPCFORC",
        "*DATABASE_BNDOUT", "*DATABASE_RBDOUT", "*DATABASE_DEFORC", "*DATABASE_JNTFORC"})
    t.push_back({name, asciiDatabase()});
  // *DATABASE_ELOUT: OPTION1-4 ask for extra history variables per point (not written).
  t.push_back({"*DATABASE_ELOUT",
               {{"card 1",
                 {R("DT"), I("BINARY", 0, Q), I("LCUR"), I("IOOPT", 0, Q), I("OPTION1"),
                  I("OPTION2"), I("OPTION3"), I("OPTION4")}}}});
  // Keyword Manual Vol. I, *DATABASE_CROSS_SECTION_PLANE: the cut's tail (XCT..) and the
  // normal's head (XCH..), the edge vector's head (XHEV..), its lengths; ID/ITYPE name a local
  // output frame.
  t.push_back(
      {"*DATABASE_CROSS_SECTION_PLANE",
       {{"id card", {I("CSID"), A("TITLE", 70)}},
        {"card 1",
         {I("PSID"), R("XCT"), R("YCT"), R("ZCT"), R("XCH"), R("YCH"), R("ZCH"), R("RADIUS")}},
        {"card 2", {R("XHEV"), R("YHEV"), R("ZHEV"), R("LENL"), R("LENM"), I("ID"), I("ITYPE")}}}});
  // Keyword Manual Vol. I, *DATABASE_CROSS_SECTION_SET: the nodes of the cut (NSID) and the
  // sets of the elements on one side of it (HSID solids, BSID beams, SSID shells, TSID thick
  // shells, DSID discretes); ID/ITYPE name a local frame.
  t.push_back({"*DATABASE_CROSS_SECTION_SET",
               {{"id card", {I("CSID"), A("TITLE", 70)}},
                {"card 1",
                 {I("NSID"), I("HSID"), I("BSID"), I("SSID"), I("TSID"), I("DSID"), I("ID"),
                  I("ITYPE")}}}});
  t.push_back({"*DATABASE_BINARY_D3PLOT",
               {{"card 1", {R("DT"), I("LCDT"), I("BEAM", 0, Q), I("NPLTC"), I("PSETID")}},
                {"card 2", {I("IOOPT", 0, Q)}}}});
  // Restart dumps: CYCL is the interval in cycles (a real in the manual's layout, "1000." and
  // "1000" both read); NR, the number of dumps kept, is fixed at two by Crumple.
  t.push_back({"*DATABASE_BINARY_D3DUMP", {{"card 1", {R("CYCL"), I("NR", 0, Q)}}}});
  t.push_back({"*DATABASE_EXTENT_BINARY",
               {{"card 1",
                 {I("NEIPH"), I("NEIPS"), I("MAXINT", 3, Z), I("STRFLG"), I("SIGFLG", 1, Z),
                  I("EPSFLG", 1, Z), I("RLTFLG", 1, Z), I("ENGFLG", 1, Z)}},
                {"card 2",
                 {I("CMPFLG"), I("IEVERP"), I("BEAMIP"), I("DCOMP", 1, Z), I("SHGE", 1, Z),
                  I("STSSZ", 1, Z), I("N3THDT", 2, Z), I("IALEMAT", 1, Z)}},
                {"card 3",
                 {I("NINTSLD"), I("PKP_SEN"), R("SCLP", 1, Z), I("HYDRO"), I("MSSCL"), I("THERM"),
                  A("INTOUT"), A("NODOUT")}}}});
  t.push_back({"*DATABASE_HISTORY_NODE",
               {idList("card 1", "ID1", "ID2", "ID3", "ID4", "ID5", "ID6", "ID7", "ID8"),
                {"id card", {I("ID"), A("HEADING", 70)}}}});
  // *DATABASE_HISTORY_SOLID, _SHELL, _BEAM: element ids, or one per card with a heading (_ID);
  // _SET: ids of *SET_SOLID, *SET_SHELL, *SET_BEAM.
  // _TSHELL, _TSHELL_SET: thick shells, *SET_TSHELL.
  for (auto [name, set] : Pairs{{"*DATABASE_HISTORY_SOLID", "*DATABASE_HISTORY_SOLID_SET"},
                                {"*DATABASE_HISTORY_SHELL", "*DATABASE_HISTORY_SHELL_SET"},
                                {"*DATABASE_HISTORY_BEAM", "*DATABASE_HISTORY_BEAM_SET"},
                                {"*DATABASE_HISTORY_TSHELL", "*DATABASE_HISTORY_TSHELL_SET"}}) {
    t.push_back({name,
                 {idList("card 1", "ID1", "ID2", "ID3", "ID4", "ID5", "ID6", "ID7", "ID8"),
                  {"id card", {I("ID"), A("HEADING", 70)}}}});
    t.push_back({set, {idList("card 1", "ID1", "ID2", "ID3", "ID4", "ID5", "ID6", "ID7", "ID8")}});
  }
  t.push_back({"*DATABASE_HISTORY_NODE_SET",
               {idList("card 1", "ID1", "ID2", "ID3", "ID4", "ID5", "ID6", "ID7", "ID8")}});
  // ---- definitions ----------------------------------------------------------------------------
  t.push_back({"*DEFINE_CURVE",
               {titleCard(),
                {"card 1",
                 {I("LCID"), I("SIDR"), R("SFA", 1, Z), R("SFO", 1, Z), R("OFFA"), R("OFFO"),
                  I("DATTYP"), I("LCINT")}},
                {"point card", {R("A1", 0, 0, 20), R("O1", 0, 0, 20)}}}});
  // Keyword Manual vol. I, *DEFINE_TABLE: one VALUE (E20.0) per card, with the LCID of its curve
  // (0: the next *DEFINE_CURVE after the table).
  t.push_back({"*DEFINE_TABLE",
               {titleCard(),
                {"card 1", {I("TBID"), R("SFA", 1, Z), R("OFFA")}},
                {"value card", {R("VALUE", 0, 0, 20), I("LCID")}}}});
  t.push_back(
      {"*DEFINE_BOX",
       {titleCard(),
        {"card 1", {I("BOXID"), R("XMN"), R("XMX"), R("YMN"), R("YMX"), R("ZMN"), R("ZMX")}}}});
  t.push_back(
      {"*DEFINE_VECTOR",
       {titleCard(),
        {"card 1", {I("VID"), R("XT"), R("YT"), R("ZT"), R("XH"), R("YH"), R("ZH"), I("CID")}}}});
  t.push_back(
      {"*DEFINE_COORDINATE_NODE",
       {titleCard(), {"card 1", {I("CID"), I("N1"), I("N2"), I("N3"), I("FLAG"), A("DIR")}}}});
  t.push_back(
      {"*DEFINE_COORDINATE_SYSTEM",
       {titleCard(),
        {"card 1", {I("CID"), R("XO"), R("YO"), R("ZO"), R("XL"), R("YL"), R("ZL"), I("CIDL")}},
        {"card 2", {R("XP"), R("YP"), R("ZP")}}}});
  // ---- sets -----------------------------------------------------------------------------------
  t.push_back({"*SET_NODE_LIST",
               {titleCard(), setCard(),
                idList("card 2", "NID1", "NID2", "NID3", "NID4", "NID5", "NID6", "NID7", "NID8"),
                rangeCard()}});
  t.push_back(
      {"*SET_NODE_GENERAL",
       {titleCard(),
        setCard(),
        {"card 2", {A("OPTION"), I("E1"), I("E2"), I("E3"), I("E4"), I("E5"), I("E6"), I("E7")}}}});
  t.push_back({"*SET_PART_LIST",
               {titleCard(), setCard(),
                idList("card 2", "PID1", "PID2", "PID3", "PID4", "PID5", "PID6", "PID7", "PID8"),
                rangeCard()}});
  // *SET_SOLID, *SET_BEAM, *SET_DISCRETE, *SET_TSHELL: SID, SOLVER; *SET_SHELL: SID, DA1-DA4,
  // SOLVER (Keyword Manual vol. I). Eight element ids per card, or _GENERATE ranges; _ADD lists
  // sets.
  for (auto [name, add] : Pairs{{"*SET_SOLID", "*SET_SOLID_ADD"},
                                {"*SET_TSHELL", "*SET_TSHELL_ADD"},
                                {"*SET_BEAM", "*SET_BEAM_ADD"},
                                {"*SET_DISCRETE", "*SET_DISCRETE_ADD"},
                                {"*SET_SHELL", "*SET_SHELL_ADD"}}) {
    CardSpec head = name == "*SET_SHELL"
                        ? setCard()
                        : CardSpec{"card 1", {I("SID"), A("SOLVER", 10, "MECH", Q)}};
    t.push_back({name,
                 {titleCard(), head,
                  idList("card 2", "K1", "K2", "K3", "K4", "K5", "K6", "K7", "K8"), rangeCard()}});
    t.push_back({add,
                 {titleCard(), head,
                  idList("card 2", "DSID1", "DSID2", "DSID3", "DSID4", "DSID5", "DSID6", "DSID7",
                         "DSID8")}});
  }
  t.push_back({"*SET_SEGMENT",
               {titleCard(),
                setCard(),
                {"card 2",
                 {I("N1"), I("N2"), I("N3"), I("N4"), R("A1", 0, Q), R("A2", 0, Q), R("A3", 0, Q),
                  R("A4", 0, Q)}}}});
  // ---- boundary conditions, loads, initial conditions, rigid walls --------------------------
  // The _NODE and _SET forms differ only in the name of the first field (NID or NSID).
  for (auto [name, first] : Pairs{{"*BOUNDARY_SPC", "NID"}, {"*BOUNDARY_SPC_SET", "NSID"}})
    t.push_back({name,
                 {idCard(),
                  {"card 1",
                   {I(first), I("CID"), I("DOFX"), I("DOFY"), I("DOFZ"), I("DOFRX"), I("DOFRY"),
                    I("DOFRZ")}}}});
  for (auto [name, first] :
       Pairs{{"*BOUNDARY_PRESCRIBED_MOTION", "NID"}, {"*BOUNDARY_PRESCRIBED_MOTION_SET", "NSID"}})
    t.push_back({name,
                 {idCard(),
                  {"card 1",
                   {I(first), I("DOF"), I("VAD"), I("LCID"), R("SF", 1, Z), I("VID"),
                    R("DEATH", 1e28, Z), R("BIRTH")}}}});
  t.push_back({"*INITIAL_VELOCITY",
               {{"card 1", {I("NSID"), I("NSIDEX"), I("BOXID"), I("IRIGID"), I("ICID")}},
                {"card 2", {R("VX"), R("VY"), R("VZ"), R("VXR"), R("VYR"), R("VZR")}},
                {"card 3", {R("VXE"), R("VYE"), R("VZE"), R("VXRE"), R("VYRE"), R("VZRE")}}}});
  // *DAMPING_GLOBAL, *DAMPING_PART_MASS(_SET), *DAMPING_PART_STIFFNESS(_SET) (Keyword Manual
  // vol. I): SF defaults to 1; the scale factors STX..SRZ all 0 mean 1 (DAMPING_GLOBAL).
  t.push_back(
      {"*DAMPING_GLOBAL",
       {{"card 1",
         {I("LCID"), R("VALDMP"), R("STX"), R("STY"), R("STZ"), R("SRX"), R("SRY"), R("SRZ")}}}});
  for (auto [name, id] : Pairs{{"*DAMPING_PART_MASS", "PID"}, {"*DAMPING_PART_MASS_SET", "PSID"}})
    t.push_back({name,
                 {{"card 1", {I(id), I("LCID"), R("SF", 1, Z), I("FLAG")}},
                  {"card 2", {R("STX"), R("STY"), R("STZ"), R("SRX"), R("SRY"), R("SRZ")}}}});
  for (auto [name, id] :
       Pairs{{"*DAMPING_PART_STIFFNESS", "PID"}, {"*DAMPING_PART_STIFFNESS_SET", "PSID"}})
    t.push_back({name, {{"card 1", {I(id), R("COEF")}}}});
  // *INITIAL_AXIAL_FORCE_BEAM (Keyword Manual vol. I): SCALE defaults to 1.
  t.push_back({"*INITIAL_AXIAL_FORCE_BEAM",
               {{"card 1", {I("BSID"), I("LCID"), R("SCALE", 1, Z), I("KBEND")}}}});
  t.push_back({"*INITIAL_VELOCITY_NODE",
               {{"card 1",
                 {I("NID"), R("VX"), R("VY"), R("VZ"), R("VXR"), R("VYR"), R("VZR"), I("ICID")}}}});
  t.push_back(
      {"*INITIAL_VELOCITY_GENERATION",
       {{"card 1",
         {I("ID"), I("STYP"), R("OMEGA"), R("VX"), R("VY"), R("VZ"), I("IVATN"), I("ICID")}},
        {"card 2",
         {R("XC"), R("YC"), R("ZC"), R("NX"), R("NY"), R("NZ"), I("PHASE"), I("IRIGID")}}}});
  for (auto [name, first] : Pairs{{"*LOAD_NODE", "NID"}, {"*LOAD_NODE_SET", "NSID"}})
    t.push_back(
        {name,
         {{"card 1",
           {I(first), I("DOF"), I("LCID"), R("SF", 1, Z), I("CID"), I("M1"), I("M2"), I("M3")}}}});
  t.push_back(
      {"*LOAD_SEGMENT",
       {{"card 1",
         {I("LCID"), R("SF", 1, Z), R("AT"), I("N1"), I("N2"), I("N3"), I("N4"), I("N5")}}}});
  t.push_back({"*LOAD_SEGMENT_SET", {{"card 1", {I("SSID"), I("LCID"), R("SF", 1, Z), R("AT")}}}});
  // *LOAD_BLAST_ENHANCED (Keyword Manual vol. I, *LOAD): UNIT 2 (SI) and BLAST 2 (surface
  // burst) by default, DEATH 1e20.
  t.push_back(
      {"*LOAD_BLAST_ENHANCED",
       {{"card 1",
         {I("BID"), R("M"), R("XBO"), R("YBO"), R("ZBO"), R("TBO"), I("UNIT", 2, Z),
          I("BLAST", 2, Z)}},
        {"card 2",
         {R("CFM"), R("CFL"), R("CFT"), R("CFP"), I("NIDBO"), R("DEATH", 1e20, Z), I("NEGPHS")}}}});
  t.push_back({"*LOAD_BLAST_SEGMENT_SET",
               {{"card 1", {I("BID"), I("SSID"), I("ALEPID"), R("SFNRB"), R("SCALEP", 1, Z)}}}});
  t.push_back(
      {"*LOAD_BODY",
       {{"card 1", {I("LCID"), R("SF", 1, Z), I("LCIDDR"), R("XC"), R("YC"), R("ZC"), I("CID")}}}});
  // *AIRBAG_SIMPLE_PRESSURE_VOLUME (Keyword Manual, *AIRBAG): the _ID heading, card 1 shared by
  // every *AIRBAG (SID SIDTYP RBID VSCA PSCA VINI MWD SPSF), the law's card 2 (CN BETA LCID
  // LCIDDR). VSCA and PSCA: 0 is the default 1.
  t.push_back({"*AIRBAG_SIMPLE_PRESSURE_VOLUME",
               {{"id card", {I("ID"), A("TITLE", 70, {}, Q)}},
                {"card 1",
                 {I("SID"), I("SIDTYP"), I("RBID"), R("VSCA", 1, Z), R("PSCA", 1, Z), R("VINI"),
                  R("MWD"), R("SPSF")}},
                {"card 2", {R("CN"), R("BETA"), I("LCID"), I("LCIDDR")}}}});
  t.push_back(
      {"*RIGIDWALL_PLANAR",
       {idCard(),
        {"card 1",
         {I("NSID"), I("NSIDEX"), I("BOXID"), R("OFFSET"), R("BIRTH"), R("DEATH", 1e20, Z),
          R("RWKSF", 1, Z)}},
        {"card 2", {R("XT"), R("YT"), R("ZT"), R("XH"), R("YH"), R("ZH"), R("FRIC"), R("WVEL")}},
        {"finite card", {R("XHEV"), R("YHEV"), R("ZHEV"), R("LENL"), R("LENM")}},
        {"moving card", {R("MASS"), R("V0")}}}});
  // *RIGIDWALL_GEOMETRIC_<shape>: card 3 depends on the shape (Keyword Manual).
  for (auto [name, card3] : std::initializer_list<std::pair<std::string_view, CardSpec>>{
           {"*RIGIDWALL_GEOMETRIC_FLAT",
            {"card 3", {R("XHEV"), R("YHEV"), R("ZHEV"), R("LENL"), R("LENM")}}},
           {"*RIGIDWALL_GEOMETRIC_PRISM",
            {"card 3", {R("XHEV"), R("YHEV"), R("ZHEV"), R("LENL"), R("LENM"), R("LENP")}}},
           {"*RIGIDWALL_GEOMETRIC_CYLINDER", {"card 3", {R("RADCYL"), R("LENCYL")}}},
           {"*RIGIDWALL_GEOMETRIC_SPHERE", {"card 3", {R("RADSPH")}}}})
    t.push_back({name,
                 {idCard(),
                  {"card 1", {I("NSID"), I("NSIDEX"), I("BOXID"), R("BIRTH"), R("DEATH", 1e20, Z)}},
                  {"card 2", {R("XT"), R("YT"), R("ZT"), R("XH"), R("YH"), R("ZH"), R("FRIC")}},
                  card3,
                  // _DISPLAY: a part for drawing the wall (Keyword Manual, *RIGIDWALL_
                  // GEOMETRIC); it carries no force.
                  {"display card", {I("PID", 0, Q), R("RO", 0, Q), R("E", 0, Q), R("PR", 0, Q)}}}});
  t.push_back({"*BOUNDARY_PRESCRIBED_MOTION_RIGID",
               {idCard(),
                {"card 1",
                 {I("PID"), I("DOF"), I("VAD"), I("LCID"), R("SF", 1, Z), I("VID"),
                  R("DEATH", 1e28, Z), R("BIRTH")}}}});
  // ---- rigid bodies and nodal constraints ------------------------------------------------------
  t.push_back({"*CONSTRAINED_RIGID_BODIES", {{"card 1", {I("PIDM"), I("PIDS"), I("IFLAG")}}}});
  t.push_back({"*CONSTRAINED_EXTRA_NODES_NODE", {{"card 1", {I("PID"), I("NID"), I("IFLAG")}}}});
  t.push_back({"*CONSTRAINED_EXTRA_NODES_SET", {{"card 1", {I("PID"), I("NSID"), I("IFLAG")}}}});
  t.push_back(
      {"*CONSTRAINED_NODAL_RIGID_BODY",
       {titleCard(),
        {"card 1",
         {I("PID"), I("CID"), I("NSID"), I("PNODE"), I("IPRT", 0, Q), I("DRFLAG"), I("RRFLAG")}},
        {"spc card", {R("CMO"), R("CON1"), R("CON2")}}}});
  t.push_back({"*CONSTRAINED_SPOTWELD",
               {{"id card", {I("WID")}},
                {"card 1",
                 {I("N1"), I("N2"), R("SN"), R("SS"), R("N"), R("M"), R("TF", 1e20, Z),
                  R("EP", 1e20, Z)}}}});
  t.push_back(
      {"*CONSTRAINED_GENERALIZED_WELD_SPOT",
       {{"id card", {I("WID")}},
        {"card 1",
         {I("NSID"), I("CID", 0, Q), I("FILTER"), I("WINDOW"), I("NPR", 0, Q), I("NPRT", 0, Q)}},
        {"card 2", {R("TFAIL", 1e20, Z), R("EPSF"), R("SN"), R("SS"), R("N"), R("M")}}}});
  t.push_back({"*CONSTRAINED_JOINT",
               {idCard(),
                {"card 1",
                 {I("N1"), I("N2"), I("N3"), I("N4"), I("N5"), I("N6"), R("RPS", 1, Z),
                  R("DAMP", 1, Z)}}}});
  t.push_back(
      {"*CONSTRAINED_JOINT_STIFFNESS",
       {{"card 1", {I("JSID"), I("PIDA"), I("PIDB"), I("CIDA"), I("CIDB"), I("JID")}},
        {"card 2", {I("LCIDPH"), I("LCIDT"), I("LCIDPS"), I("DLCIDPH"), I("DLCIDT"), I("DLCIDPS")}},
        {"card 3", {R("ESPH"), R("FMPH"), R("EST"), R("FMT"), R("ESPS"), R("FMPS")}},
        {"card 4", {R("NSAPH"), R("PSAPH"), R("NSAT"), R("PSAT"), R("NSAPS"), R("PSAPS")}}}});
  t.push_back(
      {"*LOAD_RIGID_BODY",
       {{"card 1",
         {I("PID"), I("DOF"), I("LCID"), R("SF", 1, Z), I("CID"), I("M1"), I("M2"), I("M3")}}}});
  t.push_back({"*CONSTRAINED_NODE_SET",
               {{"id card", {I("CNSID")}}, {"card 1", {I("NSID"), I("DOF"), R("TF", 1e20, Z)}}}});
  // The id of a definition Crumple does not support (*MAT_RIGID, *SECTION_SHELL, ...): the
  // first field of its first card, kept so that a reference to it can say what it is.
  t.push_back({"*UNSUPPORTED_DEFINITION", {{"card 1", {I("ID")}}}});
  std::sort(t.begin(), t.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  return t;
}

const std::vector<KeywordSpec>& tables() {
  static const std::vector<KeywordSpec> t = makeTables();
  return t;
}

}  // namespace

const CardSpec& KeywordSpec::card(std::string_view label) const {
  for (const auto& c : cards)
    if (c.label == label) return c;
  throw std::logic_error("no " + std::string(label) + " in the table of " + std::string(name));
}

FieldSlot CardSpec::slot(std::string_view name) const {
  const auto named = [&](const FieldSpec& f) { return f.name == name; };
  const auto it = std::find_if(fields.begin(), fields.end(), named);
  if (it == fields.end() || std::count_if(it, fields.end(), named) != 1)
    throw std::logic_error(std::string(it == fields.end() ? "no field " : "two fields ") +
                           std::string(name) + " in " + std::string(label));
  return {this, static_cast<std::size_t>(it - fields.begin()), it->name};
}

const KeywordSpec& keywordSpec(std::string_view name) {
  const auto& t = tables();
  auto it = std::lower_bound(t.begin(), t.end(), name,
                             [](const KeywordSpec& k, std::string_view n) { return k.name < n; });
  if (it == t.end() || it->name != name)
    throw std::logic_error("no card table for " + std::string(name));
  return *it;
}

}  // namespace crumple::deck
