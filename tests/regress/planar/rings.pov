// Rings: 12 organs placed by phyllo-export 0.1.0 from rings.cfg
// (model planar, divergence 137.5 degrees).
//
// #include this file, then place the structure with object { Rings }.
// Declare your own organ objects before the #include to use them:
// each is built at the origin, facing outward along +x, up along +y.
// This file sets no camera, light or global settings.

#ifndef (Organ)
#warning "phyllo-export: no Organ declared before the #include: a placeholder sphere of radius 1 stands in"
#declare Organ = sphere { 0, 1 texture { pigment { color rgb <0.95, 0.716666667, 0.25> } } }
#end

#declare Rings_Count = 12;
#declare Rings = union {
  object { Organ matrix <0.378376826, 0, 0,  0, 0.378376826, 0,  0, 0, 0.378376826,  0.25, 0, 0> }
  object { Organ matrix <-0.278968658, 0, 0.255627678,  0, 0.378376826, 0,  -0.255627678, 0, -0.278968658,  -0.356334215, 0, 0.326520149> }
  object { Organ matrix <0.0339065138, 0, -0.387553226,  0, 0.389033616, 0,  0.387553226, 0, 0.0339065138,  0.0548222492, 0, -0.626621175> }
  object { Organ matrix <0.24389631, 0, 0.317851859,  0, 0.4006435, 0,  -0.317851859, 0, 0.24389631,  0.458645659, 0, 0.59771866> }
  object { Organ matrix <-0.405079452, 0, -0.0714264367,  0, 0.411328456, 0,  0.0714264367, 0, -0.405079452,  -0.852559205, 0, -0.15032919> }
  object { Organ matrix <0.355088692, 0, -0.226216445,  0, 0.421024773, 0,  0.226216445, 0, 0.355088692,  0.817924231, 0, -0.521075203> }
  object { Organ matrix <-0.111257008, 0, 0.415216806,  0, 0.429864069, 0,  -0.415216806, 0, -0.111257008,  -0.276364005, 0, 1.03140451> }
  object { Organ matrix <-0.202237868, 0, -0.38849533,  0, 0.437982622, 0,  0.38849533, 0, -0.202237868,  -0.536075984, 0, -1.02979238> }
  object { Organ matrix <0.41862753, 0, 0.15236796,  0, 0.445494112, 0,  -0.15236796, 0, 0.41862753,  1.17482811, 0, 0.427602464> }
  object { Organ matrix <-0.418045851, 0, 0.173160261,  0, 0.452489569, 0,  -0.173160261, 0, -0.418045851,  -1.23447649, 0, 0.511336904> }
  object { Organ matrix <0.193999385, 0, -0.416033024,  0, 0.459041652, 0,  0.416033024, 0, 0.193999385,  0.599832549, 0, -1.28634505> }
  object { Organ matrix <0.139890989, 0, 0.443677533,  0, 0.465208816, 0,  -0.443677533, 0, 0.139890989,  0.451058699, 0, 1.43057543> }
}
