// stages.pov - scenes/stages.cfg as an animation, one include a frame:
//   phyllo-export --pov --frames 4 -o stages%03d.inc scenes/stages.cfg
//   povray +A +W640 +H480 +KFI1 +KFF4 +Iscenes/stages.pov
// POV-Ray renders frames 1 to 4 (stages1.png .. stages4.png); each reads
// the include of its frame_number.  clock runs 0 to 1 as f does.
// frames: 4
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 2.9, -4.3> look_at <0, -0.1, 0> angle 40 }
light_source { <2, 6, -3> color rgb 1.1 }
light_source { <-4, 3, -3> color rgb 0.35 shadowless }
background { rgb <0.62, 0.76, 0.90> }

#declare Seed = sphere { 0, 1 scale <0.9, 0.55, 0.75>
  texture { pigment { rgb <0.16, 0.09, 0.03> } finish { phong 0.4 } } }
#declare Floret = union {
  sphere { 0, 1 scale <0.9, 0.6, 0.75> }
  cone { <0, 0.3, 0>, 0.5, <0, 1.2, 0>, 0.1 }
  texture { pigment { rgb <0.55, 0.32, 0.05> } finish { phong 0.2 } } }
#macro Petal(Colour)
  sphere { <1, 0, 0>, 1 scale <0.5, 0.05, 0.14>
    texture { pigment { rgb Colour } finish { phong 0.3 } } }
#end
#declare PetalA = object { Petal(<1.00, 0.78, 0.06>) }
#declare PetalB = object { Petal(<0.96, 0.68, 0.04>) }

#include concat("stages", str(frame_number, -3, 0), ".inc")
object { Stages }
// The stalk and the green calyx under the head.
cylinder { <0, -3, 0>, <0, -0.05, 0>, 0.08 texture { pigment { rgb <0.3, 0.5, 0.2> } } }
sphere { 0, 1 scale <0.75, 0.25, 0.75> translate <0, -0.32, 0> texture { pigment { rgb <0.3, 0.5, 0.2> } } }
