// CIE 190:2010 UGR tables for a luminaire file: the tabular method's standard rooms,
// reflectances and luminaire layout, viewed crosswise and endwise.
#pragma once

#include <scene/photometry.h>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace rayrad::app {

/// A standard room's size in multiples of H, the height of the luminaire plane above the
/// eye: x across the line of sight, y along it.
struct UgrTableRoom {
    int x = 2, y = 2;
};
/// The table's 19 rooms: x = 2H with y = 2H … 12H, 4H likewise, 8H with y = 4H … 12H, 12H
/// with y = 4H … 8H.
extern const std::array<UgrTableRoom, 19> kUgrTableRooms;

/// Reflectances of the ceiling (the luminaire plane's cavity), the walls between the eye
/// and the luminaire plane, and the floor (the plane at the eye).
struct RoomReflectances {
    double ceiling = 0.7, walls = 0.5, floor = 0.2;
};
/// The table's five columns: 0.7/0.5/0.2, 0.7/0.3/0.2, 0.5/0.5/0.2, 0.5/0.3/0.2, 0.3/0.3/0.2.
extern const std::array<RoomReflectances, 5> kUgrTableReflectances;

/// H, m (the table does not depend on it: L² ω / L_b is the same at any scale).
constexpr double kUgrTableHeight = 2.0;
/// The observer's eye above the floor, m (seated).
constexpr double kUgrTableEyeHeight = 1.2;

/// The wall's transfer factors of a rectangular room x × y × h (three surfaces of uniform
/// exitance, floor and ceiling facing each other, exact form factors; CIE 190's Table 5
/// gives the same to three decimals): the interreflected flux the walls receive per lumen
/// that first lands on the floor (FT.FW), on the walls (FT.WW − 1, the first landing left
/// out) and on the ceiling (FT.CW).
struct WallTransferFactors {
    double fromFloor = 0, fromWalls = 0, fromCeiling = 0;
};
WallTransferFactors wallTransferFactors(double x, double y, double h, const RoomReflectances& rho);

/// One entry of the table: the luminaire `p` in a grid of spacing `spacing` × H over the
/// room's ceiling (its C0–C180 plane along the line of sight crosswise, across it endwise:
/// CIE 117's C = arctan(T/R) and 90° − arctan(T/R)), the observer at the middle of the wall
/// at the eye height, looking horizontally along y. The luminaires with T/R ≤ 3, γ ≤ 85°
/// and P ≤ 16 count, each L = I / A_p toward the eye, ω = A_p / r². L_b = E_W,ind / π, the
/// walls' mean interreflected illuminance: the direct flux on floor, walls and ceiling
/// integrated from the distribution (1° × 5° cells), times the transfer factors, over the
/// walls' area 2H(X + Y). Nothing when no luminaire counts.
struct UgrTableEntry {
    std::optional<double> ugr;
    double backgroundLuminance = 0;  ///< L_b, cd/m²
    int luminaires = 0;              ///< in the room
    int counted = 0;                 ///< within the field the formula counts
};
UgrTableEntry ugrTableEntry(const scene::Photometry& p, const UgrTableRoom& room, const RoomReflectances& rho,
                            bool endwise, double spacing);

/// The whole table: per room, the five reflectances crosswise then endwise.
struct UgrTable {
    double spacing = 0.25;  ///< S / H
    double flux = 0;        ///< the luminaire's flux, lm (∫ I dω)
    std::vector<std::array<std::optional<double>, 10>> values;  ///< per kUgrTableRooms
};
/// Throws InputError (naming the file) when the file gives no luminous area.
UgrTable ugrTable(const scene::Photometry& p, double spacing = 0.25);

/// The table as designers read it: the reflectances over ten columns, a row per room.
std::string ugrTableText(const UgrTable& table, const scene::Photometry& p);
/// The same as CSV: x_h,y_h then cross_70_50_20 … end_30_30_20 (empty: nothing counted).
std::string ugrTableCsv(const UgrTable& table);

}  // namespace rayrad::app
