// mammillaria-spines.pov - scenes/mammillaria-spines.cfg: tubercles
// spaced by the collision model, each with its own cluster of spines.
//   phyllo-export --pov -o mammillaria-spines.inc scenes/mammillaria-spines.cfg
//   povray +A +W640 +H480 +Iscenes/mammillaria-spines.pov
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3.2, -4.6> look_at <0, 0.8, 0> angle 42 }
light_source { <3, 6, -4> color rgb 1.1 }
light_source { <-4, 2, -3> color rgb 0.4 shadowless }
background { rgb <0.78, 0.72, 0.62> }

// A tubercle: a rounded cone along +y (the stem's normal).
#declare Tubercle = union {
  cone { 0, 1, <0, 0.8, 0>, 0.35 }
  sphere { <0, 0.8, 0>, 0.35 }
  texture { pigment { rgb <0.22, 0.42, 0.22> } finish { phong 0.2 } } }
// Spines: fine needles outward along +x.
#declare Spine = cone { 0, 0.05, <1, 0, 0>, 0.005
  texture { pigment { rgb <0.97, 0.96, 0.93> } } }
#declare CentralSpine = cone { 0, 0.07, <1, 0, 0>, 0.008
  texture { pigment { rgb <0.55, 0.36, 0.22> } } }

#include "mammillaria-spines.inc"
object { MammillariaSpines }
// The pot.
cone { <0, -0.8, 0>, 1.0, <0, 0.05, 0>, 1.3 open
  texture { pigment { rgb <0.7, 0.38, 0.22> } } }
disc { <0, 0, 0>, y, 1.28 texture { pigment { rgb <0.3, 0.22, 0.15> } } }
