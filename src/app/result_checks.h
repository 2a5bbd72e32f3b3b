// The last look before results are handed over: nothing non-finite, nothing all black.
// Each check throws ResultError (exit 4) naming the cause; nothing is written then.
#pragma once

#include <app/sensor_table.h>
#include <core/hdr_image.h>
#include <radiosity/radiosity.h>

#include <cstdint>
#include <string>
#include <vector>

namespace rayrad::app {

/// The rendered image (cd/m²): every value finite and within what an EXR float holds
/// (3.4e38), and not every pixel black unless `allowBlack` (a camera behind a mirror's
/// back, inside a closed object, or looking away from every lit surface).
void checkRenderedImage(const HdrImage& image, bool allowBlack);

/// The radiosity solution (solved, or read from `solutionFile` when not empty): every
/// patch's direct and indirect illuminance and every vertex value finite, else
/// ResultError naming the first (a NaN texel or an absurd light makes a NaN solution that
/// would otherwise be saved or exported).
void checkSolution(const radiosity::RadiositySolution& solution, const std::string& solutionFile);

/// The display image of a rendering that has light: not every pixel black and not
/// every pixel white, which only an exposure far off can do. `exposure` describes it
/// for the message ("auto", "-40 stops").
void checkDisplayImage(const std::string& path, const std::vector<uint8_t>& rgb8, const std::string& exposure);

/// Every sensor value finite (else ResultError); returns a warning when there are several
/// sensors and every one reads 0 lx.
std::vector<std::string> checkSensorResults(const std::vector<SensorResult>& results);

}  // namespace rayrad::app
