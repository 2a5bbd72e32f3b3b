// rayrad validate luminaire: every bundled photometric file against closed-form answers.
#pragma once

#include <string>

namespace rayrad::app {

struct ValidateLuminaireOptions {
    std::string dataDir = "tests/data/luminaires";  ///< the .ies/.ldt files
    std::string outDir = "out/validate-luminaire";
};

/// For each type C file: (1) the direct illuminance on a black floor 3 m under the
/// luminaire at every tabulated γ < 80° in its C0 and C90 planes (where no interpolation
/// is needed) against I(C, γ) cos³γ / h² from the table; (2) the luminaire at the centre
/// of a closed sphere of reflectance 0.5, where the indirect illuminance everywhere is
/// ρ/(1−ρ) Φ/A with Φ the table's integral, and the energy account. Prints a Markdown
/// table with the largest errors and the run time; writes results.csv into outDir.
/// Returns the exit code (1 when an error is beyond its bound).
int validateLuminaire(const ValidateLuminaireOptions& options);

}  // namespace rayrad::app
