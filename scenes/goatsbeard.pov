// goatsbeard.pov - scenes/goatsbeard.cfg: achenes spaced by the collision
// model on a small sphere, each with a parachute made by the planar model.
//   phyllo-export --pov -o goatsbeard.inc scenes/goatsbeard.cfg
//   povray +A +W640 +H480 +Iscenes/goatsbeard.pov
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0.5, 1.0, -5.2> look_at <0, 0.1, 0> angle 40 }
light_source { <3, 5, -4> color rgb 1.1 }
light_source { <-4, 1, -3> color rgb 0.5 shadowless }
background { rgb <0.20, 0.26, 0.36> }

// The beak: a thin stalk from the achene up its own +y (the normal),
// with the achene's dark seed at its foot.
#declare Beak = union {
  cylinder { 0, <0, 1, 0>, 0.012 texture { pigment { rgb <0.85, 0.82, 0.7> } } }
  sphere { <0, 0.06, 0>, 0.035 scale <1, 2.2, 1>
    texture { pigment { rgb <0.35, 0.25, 0.15> } } }
}
// A bristle: a fine hair outward along +x.
#declare Bristle = cylinder { 0, <1, 0, 0>, 0.007
  texture { pigment { rgb <0.97, 0.96, 0.92> } finish { ambient 0.15 } } }

#include "goatsbeard.inc"
object { Goatsbeard }
sphere { 0, 0.3 texture { pigment { rgb <0.45, 0.5, 0.3> } } }
cylinder { <0, -0.3, 0>, <0, -3, 0>, 0.06 texture { pigment { rgb <0.4, 0.5, 0.3> } } }
