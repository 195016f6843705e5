// measured-head.pov - a sunflower head measured: florets clicked on a
// photograph (scenes/measured-head.cfg reads them; synthetic, see
// scenes/points/make-sunflower-photo.py), each placed where it was with
// the seed model of sunflower.pov.  The photograph's frame cut the
// head's right edge off: so is the render.
//   phyllo-export --pov -o measured-head.inc scenes/measured-head.cfg
//   povray +A +W640 +H480 +Iscenes/measured-head.pov +Omeasured-head.png
// (make renders does both for every scene.)
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3.2, -2.4> look_at <0, -0.15, -0.05> angle 40 }
light_source { <2, 6, -3> color rgb 1.1 }
light_source { <-4, 3, -3> color rgb 0.35 shadowless }
background { rgb <0.62, 0.76, 0.90> }

// Organ models at the origin facing outward along +x, up +y, of unit
// size (scaled by each floret's measured spacing).
#declare Seed = sphere { 0, 1 scale <0.9, 0.55, 0.75>
  texture { pigment { rgb <0.16, 0.09, 0.03> } finish { phong 0.4 } } }

#include "measured-head.inc"
object { MeasuredHead }
// The receptacle the florets sit on, to the measured head's rim.
cylinder { <0, -0.06, 0>, <0, -0.01, 0>, 1.02
  texture { pigment { rgb <0.35, 0.45, 0.12> } } }
