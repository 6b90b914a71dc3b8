// Series solutions of the uniformly loaded, simply supported square plate (Navier), the truth of
// the plate problems of the studies (docs/accuracy.md, docs/stability.md) and of SPEC §7.3
// Tab 7.1b/7.2 (docs/verification.md): Timoshenko & Woinowsky-Krieger §30 for the Kirchhoff
// plate; the Mindlin plate with hard simple supports (w = 0 and no rotation along the edge) adds
// the Marcus moment over k G t (k = 5/6) to the deflection and has the same moment sum.
#pragma once

namespace styk::studies {

struct SquarePlate {
  double side = 1.0;  // a
  double thickness = 0.01;
  double young = 10.92e5;
  double poisson = 0.3;
  double pressure = 1.0;  // q, along the deflection
};

// Deflection at (x, y) in [0, a]^2: Kirchhoff (mindlin = false) or hard simply supported Mindlin.
double plate_deflection(const SquarePlate& plate, double x, double y, bool mindlin);

// The moment sum M_x + M_y (per unit length; positive where the loaded side is in compression)
// at (x, y): the same for the Kirchhoff and the hard simply supported Mindlin plate.
double plate_moment_sum(const SquarePlate& plate, double x, double y);
// Its mean over the rectangle [x0, x1] x [y0, y1] (the harmonics integrated exactly).
double plate_moment_sum_mean(const SquarePlate& plate, double x0, double x1, double y0, double y1);

}  // namespace styk::studies
