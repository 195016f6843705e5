// cone-area.pov - scenes/cone-area.cfg rendered with simple organ models.
//   phyllo-export --pov -o cone-area.inc scenes/cone-area.cfg
//   povray +A +W640 +H480 +Iscenes/cone-area.pov
// (make renders does both.)  Organs are built at the origin, outward
// along +x, up along +y (out of the surface), of unit size.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 1.8, -6> look_at <0, 1.0, 0> angle 40 }
light_source { <-5, 9, -7> color rgb 1.1 }
light_source { <6, 3, -5> color rgb 0.35 shadowless }
background { rgb <0.78, 0.84, 0.90> }

// A woody scale: a rounded plate lying along the surface, its tip
// lifted.
#declare Scale = union {
  sphere { 0, 1 scale <1.1, 0.35, 0.95> }
  sphere { <0.5, 0.25, 0>, 0.5 scale <1, 0.6, 1> }
  texture { pigment { rgb <0.45, 0.28, 0.12> } finish { phong 0.2 } }
}
#include "cone-area.inc"
object { ConeArea }

