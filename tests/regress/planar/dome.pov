// DomedHead: 7 organs placed by phyllo-export 0.1.0 from dome.cfg
// (model planar, divergence 137.507764 degrees).
//
// #include this file, then place the structure with object { DomedHead }.
// Declare your own organ objects before the #include to use them:
// each is built at the origin, facing outward along +x, up along +y.
// This file sets no camera, light or global settings.

#ifndef (Floret)
#warning "phyllo-export: no Floret declared before the #include: a placeholder sphere of radius 1 stands in"
#declare Floret = sphere { 0, 1 texture { pigment { color rgb <0.95, 0.716666667, 0.25> } } }
#end

#declare DomedHead_Count = 7;
#declare DomedHead = union {
  object { Floret matrix <0.190462561, 0, 0,  0, 0.190462561, 0,  0, 0, 0.190462561,  0, 0.5, 0> }
  object { Floret matrix <-0.107889892, -0.121931161, 0.0988359786,  -0.089908243, 0.146317393, 0.0823633155,  -0.128655612, 5.28639802e-18, -0.140441165,  -0.147473776, 0.416666667, 0.135098059> }
  object { Floret matrix <0.0107733529, -0.145226342, -0.1227568,  0.0126965182, 0.123228637, -0.144670276,  0.189733288, 1.32159951e-18, 0.0166513275,  0.0247277291, 0.333333333, -0.281759719> }
  object { Floret matrix <0.0659958043, -0.156559261, 0.0860798401,  0.0952567385, 0.108467438, 0.124245547,  -0.151151232, -5.28639802e-18, 0.115884824,  0.210769404, 0.25, 0.274911364> }
  object { Floret matrix <-0.0964942205, -0.163320299, -0.0170684689,  -0.160823701, 0.0979921794, -0.0284474482,  0.0331751404, 2.64319901e-18, -0.187551053,  -0.393885394, 0.166666667, -0.0696727802> }
  object { Floret matrix <0.0759913997, -0.167823081, -0.0483395082,  0.141601613, 0.090063316, -0.0900753553,  0.1022266, -5.28639802e-18, 0.160703795,  0.377338839, 0.0833333333, -0.240032082> }
  object { Floret matrix <-0.0217528562, -0.171040429, 0.0809195408,  -0.0444028318, 0.0837923554, 0.165176321,  -0.183932567, 0, -0.0494449009,  -0.127179616, 0, 0.473101834> }
}
