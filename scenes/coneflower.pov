// coneflower.pov - the green coneflower of scenes/coneflower.cfg: the
// collision model on a domed cone, ray florets at the base, open disk
// florets and closed buds shrinking towards the tip.
//   phyllo-export --pov -o coneflower.inc scenes/coneflower.cfg
//   povray +A +W640 +H480 +Iscenes/coneflower.pov
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 2.8, -5.6> look_at <0, 0.25, 0> angle 42 }
light_source { <-5, 9, -6> color rgb 1.1 }
light_source { <5, 3, -5> color rgb 0.35 shadowless }
background { rgb <0.78, 0.84, 0.90> }

// Organs are built at the origin, outward along +x (down the cone,
// away from its tip), up along +y (out of the surface).

// A ray floret: a drooping yellow strap about one unit long.
#declare RayFloret = union {
  sphere { 0, 1 scale <0.5, 0.02, 0.11> translate <0.5, 0, 0> }
  sphere { 0, 1 scale <0.12, 0.03, 0.06> }
  texture { pigment { rgb <0.95, 0.78, 0.10> } finish { diffuse 0.8 } }
}
// An open disk floret: a short green-gold tube opening into five
// points, of unit radius.
#declare OpenFloret = union {
  cone { <0, 0, 0>, 0.9, <0, 1.1, 0>, 0.55 }
  #for (I, 0, 4)
    cone { <0, 1.0, 0>, 0.3, <0.65, 1.5, 0>, 0 rotate y * 72 * I }
  #end
  texture { pigment { rgb <0.62, 0.60, 0.18> } finish { phong 0.2 } }
}
// A closed floret: a green bud.
#declare ClosedFloret = sphere {
  0, 1 scale <0.95, 1.1, 0.95> translate <0, 0.3, 0>
  texture { pigment { rgb <0.30, 0.48, 0.12> } finish { phong 0.3 } }
}

#include "coneflower.inc"
object { Coneflower }
// The receptacle under the florets: the scene's own Bezier profile.
lathe {
  bezier_spline 4, <1, 0>, <0.8, 0.5>, <0.35, 1.1>, <0, 1.2>
  pigment { rgb <0.35, 0.30, 0.10> }
}
// The stem.
cylinder { <0, -3, 0>, <0, 0.05, 0>, 0.12 pigment { rgb <0.25, 0.42, 0.12> } }
