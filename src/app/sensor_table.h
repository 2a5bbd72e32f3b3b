// Sensor results: the illuminance table printed on stdout and written as CSV.
#pragma once

#include <radiosity/radiosity.h>
#include <scene/scene.h>

#include <optional>
#include <string>
#include <vector>

namespace rayrad::app {

struct SensorResult {
    scene::Sensor sensor;
    radiosity::SensorValue value;
    /// Why the point is no measurement — "inside a solid", "buried" (under a surface
    /// within a few millimetres) — or "": such grid points are left out of the grid's
    /// statistics, and the CSV marks them.
    std::string excluded;
    /// Daylight without direct sun: the daylight factor, 100 · E / E_out (E_out the
    /// unobstructed sky's horizontal illuminance), %.
    std::optional<double> daylightFactor;
};

/// CSV with the columns
/// sensor,x,y,z,nx,ny,nz,direct_lx,indirect_lx,total_lx
/// then, when any sensor has a reference, ref_direct_lx,ref_indirect_lx,ref_total_lx,
/// err_direct_pct,err_indirect_pct,err_total_pct (100·(value − ref)/ref, empty where
/// no reference), then indirect_vertex_lx (interpolated vertex values; empty off-surface)
/// and, with references, err_indirect_vertex_pct; then, under a sky without sun,
/// daylight_factor_pct. Illuminances are luminance-weighted Y.
std::string sensorCsv(const std::vector<SensorResult>& results);

/// Whether any result carries a daylight factor.
bool anyDaylightFactor(const std::vector<SensorResult>& results);

/// A CSV field: quoted (quotes doubled) when it holds a comma, a quote or a newline.
std::string csvField(const std::string& text);

/// The same as an aligned text table for the terminal.
std::string sensorTable(const std::vector<SensorResult>& results);

}  // namespace rayrad::app
