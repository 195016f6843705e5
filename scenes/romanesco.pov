// romanesco.pov - scenes/romanesco.cfg: a cone of florets that are cones
// of buds, two levels of the collision model.  The include declares the
// floret (a part) once and places it 114 times:
//   phyllo-export --pov -o romanesco.inc scenes/romanesco.cfg
//   povray +A +W640 +H480 +Iscenes/romanesco.pov
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 2.3, -4.4> look_at <0, 0.62, 0> angle 38 }
light_source { <3, 6, -4> color rgb 1.1 }
light_source { <-4, 2, -3> color rgb 0.4 shadowless }
background { rgb <0.86, 0.88, 0.84> }

// A bud: a rounded knob, outward along +x, its top along +y.
#declare Bud = sphere { 0, 1 scale <1, 0.8, 1>
  texture { pigment { rgb <0.52, 0.72, 0.18> } finish { phong 0.3 } } }

#include "romanesco.inc"
object { Romanesco }
// The cone under the florets, so no gaps show through.
cone { 0, 1.0, <0, 1.2, 0>, 0 texture { pigment { rgb <0.42, 0.6, 0.14> } } }
