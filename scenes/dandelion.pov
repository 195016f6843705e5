// dandelion.pov - scenes/dandelion.cfg rendered with simple organ models.
//   phyllo-export --pov -o dandelion.inc scenes/dandelion.cfg
//   povray +A +W640 +H480 +Iscenes/dandelion.pov
// (make renders does both.)  Organs are built at the origin, outward
// along +x, up along +y (out of the surface), of unit size.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 1.6, -6.4> look_at <0, 1.05, 0> angle 40 }
light_source { <-5, 9, -7> color rgb 1.1 }
light_source { <6, 3, -5> color rgb 0.35 shadowless }
background { rgb <0.55, 0.70, 0.85> }

// A seed on its stalk, topped by a white tuft.
#declare Pappus = union {
  cylinder { <0, 0, 0>, <0, 2.6, 0>, 0.06 pigment { rgb <0.85, 0.82, 0.70> } }
  sphere { 0, 0.6 scale <1, 0.35, 1> translate <0, 2.6, 0>
    pigment { rgbt <1, 1, 1, 0.35> } finish { diffuse 0.9 } }
}
#include "dandelion.inc"
object { Dandelion }
// The receptacle.
sphere { <0, 1, 0>, 0.97 pigment { rgb <0.55, 0.45, 0.25> } }
cylinder { <0, -3, 0>, <0, 0.1, 0>, 0.08 pigment { rgb <0.45, 0.55, 0.30> } }
