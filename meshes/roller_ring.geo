// femcam roller ring (full annulus) on its pin: the geometry of femcam.bodies.mesh (mesh_ring,
// mesh_disk). Defaults from roller_ring.toml. Units: mm. Open in the gmsh GUI and move the sliders:
//     gmsh meshes/roller_ring.geo
// Frame: ring and pin centre (0, Ro); the cam touches the ring at the origin (y from cam to
// roller). The fine arc |x| <= xf at the bottom is the cam contact; the bore and the pin surface
// carry n_bore vertices uniform in angle from -90 deg.
// Differences from the API, on purpose: the API snaps the fine-arc vertices to the cam's exact
// uniform abscissae and meshes ring and pin as two separate models (no shared nodes); here both
// are drawn in one model (the pin only when pin = 1).
SetFactory("Built-in");
DefineConstant[
  Ro = {10.0, Min 2, Max 100, Step 0.5, Name "Geometry/Ring outer radius Ro (mm)"},
  Ri = {7.0, Min 0.5, Max 99, Step 0.1, Name "Geometry/Ring bore radius Ri (mm)"},
  Rp = {4.99, Min 0.1, Max 99, Step 0.01, Name "Geometry/Pin radius Rp (mm)"},
  pin = {1, Choices{0 = "ring only", 1 = "ring and pin"}, Name "Geometry/Draw the pin"},
  a_ref = {0.105, Min 0.001, Max 1, Step 0.005, Name "Mesh/Reference half-width a_ref (mm)"},
  a_over_h = {20, Min 2, Max 80, Step 1, Name "Mesh/a_ref over h"},
  fine_half_width = {2.5, Min 1.2, Max 10, Step 0.1, Name "Mesh/fine zone half-width (x a_ref)"},
  fine_depth = {0.6, Min 0, Max 5, Step 0.1, Name "Mesh/fine band depth (x a_ref)"},
  n_bore = {128, Min 16, Max 1024, Step 4, Name "Mesh/bore vertices (multiple of 4)"},
  h_max_over_wall = {0.25, Min 0.02, Max 1, Step 0.01, Name "Mesh/largest element (x wall)"},
  growth = {0.3, Min 0.05, Max 1, Step 0.05, Name "Mesh/size growth slope"},
  band = {3, Min 0, Max 10, Step 0.5, Name "Mesh/bore band (x bore spacing)"}
];
If (Ri >= Ro)
  Error("Ri = %g mm must be < Ro = %g mm", Ri, Ro);
  Abort;
EndIf
If (pin && Rp >= Ri)
  Error("Rp = %g mm must be < Ri = %g mm", Rp, Ri);
  Abort;
EndIf
h = a_ref / a_over_h;
n_fine = Round(2 * fine_half_width * a_ref / h);
xf = 0.5 * n_fine * h;
h_max = h_max_over_wall * (Ro - Ri);
hb = 2 * Pi * Ri / n_bore;
If (hb > h_max)
  hb = h_max;
EndIf
q = n_bore / 4;
cy = Ro;
a0 = -Pi / 2 - Asin(xf / Ro);
a1 = -Pi / 2 + Asin(xf / Ro);
// outer circle: fine arc a0..a1, then 0, pi/2, pi and back to a0
Point(1) = {0, cy, 0, h_max};
Point(2) = {Ro * Cos(a0), cy + Ro * Sin(a0), 0, h_max};
Point(3) = {Ro * Cos(a1), cy + Ro * Sin(a1), 0, h_max};
Point(4) = {Ro, cy, 0, h_max};
Point(5) = {0, cy + Ro, 0, h_max};
Point(6) = {-Ro, cy, 0, h_max};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Circle(3) = {4, 1, 5};
Circle(4) = {5, 1, 6};
Circle(5) = {6, 1, 2};
// bore: quarter arcs from -90 deg
Point(11) = {0, cy - Ri, 0, h_max};
Point(12) = {Ri, cy, 0, h_max};
Point(13) = {0, cy + Ri, 0, h_max};
Point(14) = {-Ri, cy, 0, h_max};
Circle(11) = {11, 1, 12};
Circle(12) = {12, 1, 13};
Circle(13) = {13, 1, 14};
Circle(14) = {14, 1, 11};
Curve Loop(1) = {1, 2, 3, 4, 5};
Curve Loop(2) = {11, 12, 13, 14};
Plane Surface(1) = {1, 2};
Transfinite Curve{1} = n_fine + 1;
Transfinite Curve{11, 12, 13, 14} = q + 1;
Physical Curve("ring_contact") = {1};
Physical Curve("ring_bore") = {11, 12, 13, 14};
Physical Surface("ring") = {1};
If (pin)
  Point(21) = {0, cy - Rp, 0, h_max};
  Point(22) = {Rp, cy, 0, h_max};
  Point(23) = {0, cy + Rp, 0, h_max};
  Point(24) = {-Rp, cy, 0, h_max};
  Circle(21) = {21, 1, 22};
  Circle(22) = {22, 1, 23};
  Circle(23) = {23, 1, 24};
  Circle(24) = {24, 1, 21};
  Curve Loop(3) = {21, 22, 23, 24};
  Plane Surface(2) = {3};
  Transfinite Curve{21, 22, 23, 24} = q + 1;
  Physical Curve("pin_surface") = {21, 22, 23, 24};
  Physical Surface("pin") = {2};
EndIf
// size: h near the fine arc, the bore spacing near the bore (and pin), growing with slope growth
Field[1] = Distance;
Field[1].CurvesList = {1};
Field[1].Sampling = 400;
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h;
Field[2].SizeMax = h_max;
Field[2].DistMin = fine_depth * a_ref;
Field[2].DistMax = fine_depth * a_ref + (h_max - h) / growth;
Field[3] = Distance;
Field[3].CurvesList = {11, 12, 13, 14};
If (pin)
  Field[3].CurvesList = {11, 12, 13, 14, 21, 22, 23, 24};
EndIf
Field[3].Sampling = 400;
Field[4] = Threshold;
Field[4].InField = 3;
Field[4].SizeMin = hb;
Field[4].SizeMax = h_max;
Field[4].DistMin = band * hb;
Field[4].DistMax = band * hb + (h_max - hb) / growth;
Field[5] = Min;
Field[5].FieldsList = {2, 4};
Background Field = 5;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.Algorithm = 6;
Mesh.ElementOrder = 1;
