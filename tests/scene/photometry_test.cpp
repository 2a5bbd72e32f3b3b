// Photometric files: IES LM-63 and EULUMDAT parsing, symmetry, integration.
#include <core/input_error.h>
#include <scene/photometry.h>

#include "test_support.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

using namespace rayrad;
using namespace rayrad::scene;
using rayrad::test::sourcePath;

namespace {

/// An IES file (metres; photometric type 1 C, 2 B, 3 A) with the given angles and candela.
std::string iesFile(const std::string& version, const std::string& vertical, const std::string& horizontal,
                    const std::string& candela, size_t nv, size_t nh, const std::string& factors = "1.0 1.0 10",
                    const std::string& lamp = "1 1000 1.0", int type = 1) {
    std::ostringstream s;
    s << version << "\n[TEST] synthetic\nTILT=NONE\n"
      << lamp << " " << nv << " " << nh << " " << type << " 2 0.5 0.5 0\n"
      << factors << "\n" << vertical << "\n" << horizontal << "\n" << candela << "\n";
    return s.str();
}

std::string repeat(const std::string& value, size_t n) {
    std::string out;
    for (size_t i = 0; i < n; ++i) out += value + " ";
    return out;
}

std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST_CASE("every bundled luminaire file integrates to the independent reference in expected.csv", "[scene][photometry]") {
    // tests/data/luminaires/expected.csv: an independent exact integration of the bilinear
    // grid (the README there says how); rayrad's must agree to rounding.
    std::ifstream csv(sourcePath("tests/data/luminaires/expected.csv"));
    REQUIRE(csv);
    std::string line;
    std::getline(csv, line);  // header
    int files = 0;
    while (std::getline(csv, line)) {
        const std::string file = line.substr(0, line.find(','));
        // integrated_lumens is the fifth column; the fourth may hold quoted commas.
        std::vector<std::string> cells;
        std::string cell;
        bool quoted = false;
        for (char c : line) {
            if (c == '"') quoted = !quoted;
            else if (c == ',' && !quoted) cells.push_back(cell), cell.clear();
            else cell += c;
        }
        cells.push_back(cell);
        const double expected = std::stod(cells[4]);
        const Photometry p = readPhotometry(sourcePath("tests/data/luminaires/" + file));
        INFO(file);
        CHECK(p.integratedFlux() == Approx(expected).margin(0.005 + 1e-9));  // the reference has two decimals
        if (!cells[6].empty()) {  // EULUMDAT's stated LOR, against the integral; see the README for sample_05
            REQUIRE(p.statedLor);
            CHECK(*p.statedLor == Approx(std::stod(cells[6])).epsilon(1e-6));
        }
        ++files;
    }
    CHECK(files == 11);
}

TEST_CASE("an isotropic source integrates to 4 pi I in every symmetry and both formats", "[scene][photometry]") {
    const double I = 100;
    std::string v;
    for (int a = 0; a <= 180; a += 10) v += std::to_string(a) + " ";
    const size_t nv = 19;
    const Photometry rotational = parseIes(iesFile("IESNA:LM-63-2002", v, "0", repeat("100", nv), nv, 1), "iso.ies");
    const Photometry quadrant = parseIes(iesFile("IESNA:LM-63-2002", v, "0 45 90", repeat("100", 3 * nv), nv, 3), "q.ies");
    const Photometry half = parseIes(iesFile("IESNA:LM-63-2002", v, "0 90 180", repeat("100", 3 * nv), nv, 3), "h.ies");
    const Photometry other = parseIes(iesFile("IESNA:LM-63-2002", v, "90 180 270", repeat("100", 3 * nv), nv, 3), "o.ies");
    const Photometry full = parseIes(iesFile("IESNA:LM-63-2002", v, "0 120 240 360", repeat("100", 4 * nv), nv, 4), "f.ies");
    for (const Photometry* p : {&rotational, &quadrant, &half, &other, &full}) {
        INFO(p->file << ": " << p->symmetry());
        CHECK(p->integratedFlux() == Approx(4 * kPi * I).epsilon(1e-12));
        CHECK(p->intensity(37, 211) == Approx(I));
    }
    CHECK(rotational.symmetry() == "rotational (one plane)");
    CHECK(quadrant.symmetry() == "quadrant (0–90)");
    CHECK(half.symmetry() == "bilateral (0–180)");
    CHECK(other.symmetry() == "bilateral (90–270)");
}

TEST_CASE("types B and A: planes about the width or the length, cos V weighting, mirrored halves", "[scene][photometry]") {
    const std::string v = "-90 -45 0 45 90", h = "-90 -45 0 45 90";
    // Isotropic over the front hemisphere (H, V in ±90): 2 π I, in both types and stored
    // whole or as the 0–90 quarter that mirrors about both axes.
    for (int type : {2, 3}) {
        const Photometry whole = parseIes(iesFile("IESNA:LM-63-2002", v, h, repeat("100", 25), 5, 5, "1.0 1.0 10", "1 1000 1.0", type), "b.ies");
        const Photometry quarter = parseIes(iesFile("IESNA:LM-63-2002", "0 45 90", "0 45 90", repeat("100", 9), 3, 3, "1.0 1.0 10", "1 1000 1.0", type), "q.ies");
        INFO("type " << type);
        CHECK(whole.type == (type == 2 ? PhotometricType::B : PhotometricType::A));
        CHECK(whole.integratedFlux() == Approx(2 * kPi * 100).epsilon(1e-12));
        CHECK(quarter.integratedFlux() == Approx(2 * kPi * 100).epsilon(1e-12));
        CHECK(quarter.intensityToward(0.3, -0.4, std::sqrt(0.75)) == Approx(100));
        CHECK(whole.intensityToward(0, 0, -1) == 0);  // behind the luminaire: no H reaches it
        CHECK(quarter.intensityToward(0.6, 0, -0.8) == 0);
    }
    // I = 300 + H + 2 V (degrees): the frame (x along C0, y along C90, z along the nadir)
    // maps to the angles as documented.
    std::string cd;
    for (int hh = -90; hh <= 90; hh += 45)
        for (int vv = -90; vv <= 90; vv += 45) cd += std::to_string(300 + hh + 2 * vv) + " ";
    const Photometry b = parseIes(iesFile("IESNA:LM-63-2002", v, h, cd, 5, 5, "1.0 1.0 10", "1 1000 1.0", 2), "b.ies");
    const Photometry a = parseIes(iesFile("IESNA:LM-63-2002", v, h, cd, 5, 5, "1.0 1.0 10", "1 1000 1.0", 3), "a.ies");
    const double s = std::sqrt(0.5);
    CHECK(b.intensityToward(0, 0, 1) == Approx(300));            // the nadir is H = V = 0
    CHECK(b.intensityToward(s, 0, s) == Approx(300 + 45));       // toward C0: H = 45
    CHECK(b.intensityToward(0, s, s) == Approx(300 + 90));       // toward C90: V = 45
    CHECK(b.intensityToward(-s, -s, 0) == Approx(300 - 90 - 90)); // H = -90, V = -45
    CHECK(a.intensityToward(s, 0, s) == Approx(300 + 90));       // type A: toward C0 is V = 45
    CHECK(a.intensityToward(0, s, s) == Approx(300 + 45));       // and toward C90 is H = 45
    // A type C file answers in the same frame: γ from the nadir, C from C0 toward C90.
    const Photometry q = parseIes(iesFile("IESNA:LM-63-2002", "0 90", "0 90", "100 100 190 190", 2, 2), "q.ies");
    CHECK(q.intensityToward(0.5 * s, 0.5 * std::sqrt(1.5), s) == Approx(160));  // γ 45, C 60
}

TEST_CASE("symmetries unfold: a quadrant file answers for every azimuth", "[scene][photometry]") {
    // I = 100 + C (degrees) on C0..C90, the same at every vertical angle.
    const Photometry q = parseIes(iesFile("IESNA:LM-63-2002", "0 90", "0 90", "100 100 190 190", 2, 2), "q.ies");
    CHECK(q.intensity(45, 30) == Approx(130));
    CHECK(q.intensity(45, 150) == Approx(130));  // mirrored about C90
    CHECK(q.intensity(45, 210) == Approx(130));  // about C180
    CHECK(q.intensity(45, 330) == Approx(130));  // about C270
    CHECK(q.intensity(120, 30) == 0);            // beyond the tabulated vertical range
    // A half-space table: ∫ over the lower hemisphere of the mean over C, 145 cd.
    CHECK(q.integratedFlux() == Approx(2 * kPi * 145).epsilon(1e-12));
}

TEST_CASE("LM-63-2019 does not multiply by the file-generation field but older versions multiply by their factors",
          "[scene][photometry]") {
    const std::string v = "0 90 180", c = repeat("10", 3);
    const Photometry y2019 = parseIes(iesFile("IES:LM-63-2019", v, "0", c, 3, 1, "0.8 1.10 5"), "a.ies");
    const Photometry y1995 = parseIes(iesFile("IESNA:LM-63-1995", v, "0", c, 3, 1, "0.8 0.5 5"), "b.ies");
    const Photometry multiplied = parseIes(iesFile("IESNA:LM-63-2002", v, "0", c, 3, 1, "1 1 5", "2 500 3.0"), "c.ies");
    CHECK(y2019.candela[0][0] == Approx(8));        // ballast factor only
    CHECK(y1995.candela[0][0] == Approx(4));        // ballast × ballast-lamp factor
    CHECK(multiplied.candela[0][0] == Approx(30));  // the candela multiplier
    CHECK(multiplied.lampFlux == Approx(1000));     // 2 lamps × 500 lm
    const Photometry absolute = parseIes(iesFile("IESNA:LM-63-2002", v, "0", c, 3, 1, "1 1 5", "1 -1 1"), "d.ies");
    CHECK(absolute.absolute);
    CHECK(absolute.lampFlux == 0);
}

TEST_CASE("TILT=INCLUDE, comma-separated numbers wrapped anywhere, feet and round openings", "[scene][photometry]") {
    const std::string text =
        "IESNA91\n[TEST] x\nTILT=INCLUDE\n1\n3\n0 45,90\n1.0 0.9\n0.8\n"
        "1,1000,1,2,1,1,1,-0.5,0,0\n1,1,\n20\n0,180\n0\n50,50\n";
    const Photometry p = parseIes(text, "tilt.ies");
    CHECK(p.tiltAngles == std::vector<double>{0, 45, 90});
    CHECK(p.tiltFactors == std::vector<double>{1.0, 0.9, 0.8});
    CHECK(p.round);
    CHECK(p.width == Approx(0.5 * 0.3048));
    CHECK(p.integratedFlux() == Approx(4 * kPi * 50));
}

TEST_CASE("EULUMDAT with decimal commas and the C0-C180 symmetry", "[scene][photometry]") {
    std::ostringstream s;
    s << "maker\n1\n2\n4\n90\n3\n90\nreport\nname\nnumber\nfile.ldt\ndate\n"
         "600\n600\n50\n590\n590\n0\n0\n0\n0\n100\n80,5\n1\n0\n1\n1\nLED\n2000\n3000\n80\n20,5\n";
    for (int i = 0; i < 10; ++i) s << "0\n";
    for (int c : {0, 90, 180, 270}) s << c << "\n";
    for (int g : {0, 90, 180}) s << g << "\n";
    for (int plane = 0; plane < 3; ++plane) s << "400\n400\n400\n";  // C0, C90, C180: 400 cd/klm
    const Photometry p = parseLdt(s.str(), "sym2.ldt");
    CHECK(p.format == "EULUMDAT");
    CHECK(p.symmetry() == "bilateral (0–180)");
    CHECK(p.horizontal == std::vector<double>{0, 90, 180});
    CHECK(p.candela[1][1] == Approx(800));  // 400 cd/klm × 2000 lm
    CHECK(p.statedLor == Approx(0.805));
    CHECK(p.inputWatts == Approx(20.5));
    CHECK(p.integratedFlux() == Approx(4 * kPi * 800));
}

TEST_CASE("EULUMDAT with two lamp sets: set by set, six lines each, the first set used", "[scene][photometry]") {
    // As DIALux and manufacturers' files lay them out: lamps, type, flux, colour, CRI,
    // watts of set 1, then the same of set 2. Read as six blocks of two lines instead, set
    // 1's flux was taken from its colour rendering line (80 lm for 2 000).
    auto file = [](bool secondSet) {
        std::ostringstream s;
        s << "maker\n1\n1\n1\n0\n3\n90\nreport\nname\nnumber\nfile.ldt\ndate\n"
             "600\n600\n50\n590\n590\n0\n0\n0\n0\n100\n80\n1\n0\n"
          << (secondSet ? 2 : 1) << "\n1\nLED 830\n2000\n3000\n80\n20\n";
        if (secondSet) s << "2\nLED 840\n4500\n4000\n80\n41\n";
        for (int i = 0; i < 10; ++i) s << "0\n";
        s << "0\n";                                         // C angles
        for (int g : {0, 90, 180}) s << g << "\n";          // γ angles
        s << "400\n400\n400\n";                             // 400 cd/klm
        return s.str();
    };
    const Photometry one = parseLdt(file(false), "one.ldt"), two = parseLdt(file(true), "two.ldt");
    CHECK(two.lampSets == 2);
    CHECK(two.lampType == "LED 830");
    CHECK(two.lampCount == 1);
    CHECK(two.lampFlux == Approx(2000));
    CHECK(two.inputWatts == Approx(20));
    CHECK(two.candela == one.candela);  // 800 cd: 400 cd/klm × set 1's 2 000 lm
    CHECK(two.candela[0][1] == Approx(800));
    // A second set cut short is an error, not a table read from the wrong lines.
    std::string shortSet = file(true);
    shortSet.replace(shortSet.find("4500\n"), 5, "");
    CHECK_THROWS_AS(parseLdt(shortSet, "short.ldt"), InputError);
}

TEST_CASE("a malformed photometric file is an error naming the line", "[scene][photometry]") {
    const std::string v = "0 90 180";
    CHECK(errorOf([&] { parseIes("IESNA:LM-63-2002\n[TEST] x\n", "a.ies"); }) ==
          "a.ies: no TILT= line: not an IES LM-63 photometric file");
    CHECK(errorOf([&] { parseIes(iesFile("IESNA:LM-63-2002", v, "0", "1 2", 3, 1), "b.ies"); }) ==
          "b.ies: line 8: the file ends before candela value 3 of 3 (horizontal angle 0, vertical 180)");
    CHECK(errorOf([&] { parseIes(iesFile("IESNA:LM-63-2002", "0 90 x", "0", "1 2 3", 3, 1), "c.ies"); }) ==
          "c.ies: line 6: expected vertical angle 3 of 3, got 'x'");
    CHECK(errorOf([&] { parseIes(iesFile("IESNA:LM-63-2002", "0 90 45", "0", "1 2 3", 3, 1), "d.ies"); }) ==
          "d.ies: line 6: vertical angles must increase: 45 after 90");
    CHECK(errorOf([&] { parseIes(iesFile("IESNA:LM-63-2002", v, "0", "1 -2 3", 3, 1), "e.ies"); }) ==
          "e.ies: line 8: candela value -2 is negative");
    CHECK(errorOf([&] { parseIes(iesFile("IESNA:LM-63-2002", v, "0", "1 2 3", 3, 1, "1 1 5", "1 0 1"), "f.ies"); }) ==
          "f.ies: line 4: lumens per lamp must be positive, or -1 for absolute photometry; got 0");
    // One horizontal angle counted, two listed: the table would be shifted by one value.
    CHECK(errorOf([&] {
              parseIes("IESNA:LM-63-2002\nTILT=NONE\n1 1000 1 3 1 1 2 0 0 0\n1 1 10\n0 45 90\n0 90\n100 50 0\n", "m.ies");
          }) == "m.ies: line 7: 1 number(s) after the 3 × 1 candela values (the first '0'): the counts of vertical and "
                "horizontal angles do not match the data");
    CHECK(errorOf([&] { parseLdt("maker\n1\n7\n", "g.ldt"); }) ==
          "g.ldt: line 3: expected the symmetry indicator Isym (0–4) (a whole number from 0 to 4), got 7");
    CHECK(errorOf([&] { parseLdt("maker\n1\n1\n1\n0\n3\n", "h.ldt"); }).find("h.ldt: line 6: the file ends before line") == 0);
    CHECK(errorOf([&] { readPhotometry(sourcePath("tests/data/luminaires/nothere.ies")); }).find("no such file") !=
          std::string::npos);
    CHECK(errorOf([&] { readPhotometry("x.txt"); }) == "x.txt: unknown photometric file type '.txt' (use .ies or .ldt)");
}

TEST_CASE("every test file's flux, integrated a second way: over directions, not over the table",
          "[scene][photometry]") {
    // integratedFlux() integrates the stored planes exactly (sin or cos weighted) and unfolds
    // the symmetries; here Φ = ∫ I dΩ is summed over a fine grid of directions through
    // intensityToward, which knows nothing of the table's layout: a symmetry unfolded
    // wrongly, or a plane counted twice, shows as a difference.
    namespace fs = std::filesystem;
    int files = 0;
    for (const auto& entry : fs::directory_iterator(sourcePath("tests/data/luminaires"))) {
        if (!isPhotometricFile(entry.path().string())) continue;
        const Photometry p = readPhotometry(entry.path().string());
        constexpr int kRings = 720, kSectors = 1440;  // in cos θ and φ: equal solid angles
        double flux = 0;
        for (int i = 0; i < kRings; ++i) {
            const double z = -1 + 2 * (i + 0.5) / kRings, r = std::sqrt(1 - z * z);
            for (int j = 0; j < kSectors; ++j) {
                const double phi = 2 * kPi * (j + 0.5) / kSectors;
                flux += p.intensityToward(r * std::cos(phi), r * std::sin(phi), z);
            }
        }
        flux *= 4 * kPi / (double(kRings) * kSectors);
        INFO(entry.path().filename().string() << ": " << p.symmetry());
        CHECK(flux == Approx(p.integratedFlux()).epsilon(2e-3));
        ++files;
    }
    CHECK(files >= 10);
}

TEST_CASE("type B with lateral symmetry (0–90 mirrored) integrates to the hemisphere it lights",
          "[scene][photometry]") {
    // 100 cd toward every direction of the front hemisphere (H −90…90 from 0…90, V −90…90):
    // Φ = 100 cd × 2π sr.
    const Photometry p = parseIes(
        "IESNA:LM-63-2002\nTILT=NONE\n1 628.3185 1 3 3 2 2 0 0 0\n1 1 10\n-90 0 90\n0 45 90\n"
        "100 100 100\n100 100 100\n100 100 100\n",
        "b.ies");
    CHECK(p.symmetry() == "bilateral (0–90, mirrored)");
    CHECK(p.integratedFlux() == Approx(2 * kPi * 100));
    CHECK(p.intensityToward(-0.6, 0, 0.8) == Approx(100));  // H −37°: the mirrored half
    CHECK(p.intensityToward(0, 0, -1) == 0);                 // behind
}
