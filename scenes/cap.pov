// cap.pov - scenes/cap.cfg rendered with simple organ models.
//   phyllo-export --pov -o cap.inc scenes/cap.cfg
//   povray +A +W640 +H480 +Iscenes/cap.pov
// (make renders does both.)  Organs are built at the origin, outward
// along +x, up along +y (out of the surface), of unit size.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 2.3, -3.0> look_at <0, 0.05, 0> angle 40 }
light_source { <-5, 9, -7> color rgb 1.1 }
light_source { <6, 3, -5> color rgb 0.35 shadowless }
background { rgb <0.80, 0.85, 0.75> }

// A disk floret: a short tube with a rounded top.
#declare Floret = union {
  cylinder { 0, <0, 0.8, 0>, 0.8 }
  sphere { <0, 0.8, 0>, 0.8 scale <1, 0.5, 1> }
  texture { pigment { rgb <0.85, 0.45, 0.10> } finish { phong 0.3 } }
}
#include "cap.inc"
object { Cap }

// The receptacle under the florets: the cap's own sphere above y = 0.
intersection {
  sphere { <0, 0.45 - 1.3361, 0>, 1.33 }
  plane { -y, 0 }
  pigment { rgb <0.35, 0.45, 0.15> }
}
