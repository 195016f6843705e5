// Vogel90: 5 organs placed by phyllo-export 0.1.0 from vogel90.cfg
// (model planar, divergence 90 degrees).
//
// #include this file, then place the structure with object { Vogel90 }.
// Declare your own organ objects before the #include to use them:
// each is built at the origin, facing outward along +x, up along +y.
// This file sets no camera, light or global settings.

#ifndef (Seed)
#warning "phyllo-export: no Seed declared before the #include: a placeholder sphere of radius 1 stands in"
#declare Seed = sphere { 0, 1 texture { pigment { color rgb <0.95, 0.716666667, 0.25> } } }
#end

#declare Vogel90_Count = 5;
#declare Vogel90 = union {
  object { Seed matrix <0.952312807, 0, 0,  0, 0.952312807, 0,  0, 0, 0.952312807,  0, 0, 0> }
  object { Seed matrix <5.83123415e-17, 0, 0.952312807,  0, 0.952312807, 0,  -0.952312807, 0, 5.83123415e-17,  6.123234e-17, 0, 1> }
  object { Seed matrix <-0.952312807, 0, 1.16624683e-16,  0, 0.952312807, 0,  -1.16624683e-16, 0, -0.952312807,  -1.41421356, 0, 1.73191211e-16> }
  object { Seed matrix <-1.74937025e-16, 0, -0.952312807,  0, 0.952312807, 0,  0.952312807, 0, -1.74937025e-16,  -3.18172572e-16, 0, -1.73205081> }
  object { Seed matrix <0.952312807, 0, 0,  0, 0.952312807, 0,  0, 0, 0.952312807,  2, 0, 0> }
}
