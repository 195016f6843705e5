// ellipsoid.pov - scenes/ellipsoid.cfg rendered with simple organ models.
//   phyllo-export --pov -o ellipsoid.inc scenes/ellipsoid.cfg
//   povray +A +W640 +H480 +Iscenes/ellipsoid.pov
// (make renders does both.)  Organs are built at the origin, outward
// along +x, up along +y (out of the surface), of unit size.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 2.4, -6.2> look_at <0, 1.5, 0> angle 40 }
light_source { <-5, 9, -7> color rgb 1.1 }
light_source { <6, 3, -5> color rgb 0.35 shadowless }
background { rgb <0.85, 0.85, 0.78> }

// A low bump on the skin.
#declare Bump = sphere { 0, 1 scale <1, 0.45, 1>
  texture { pigment { rgb <0.55, 0.65, 0.20> } finish { phong 0.4 } } }
#include "ellipsoid.inc"
object { Ellipsoid }
// The fruit under the bumps.
sphere { 0, 1 scale <1.19, 1.49, 0.79> translate <0, 1.5, 0>
  pigment { rgb <0.40, 0.50, 0.15> } }
