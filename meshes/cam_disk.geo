// femcam cam disk on its shaft: the geometry of femcam.bodies.cam_mesh (mesh_cam_disk) and of the
// shaft (femcam.bodies.mesh.mesh_disk). Defaults from cam_disk.toml. Units: mm. Open in the gmsh
// GUI and move the sliders:
//     gmsh meshes/cam_disk.geo
// Frame: the cam frame (cam centre at the origin), as the global model (femcam.bodies.cam_global).
// Differences from the API, on purpose: the API draws the cam outline as a spline through the
// profile of the scene (femcam.profile, 720 points) and, in the fully refined model
// (femcam.bodies.cam_model), replaces it at the contact by the osculating arc with today's fine
// zone; here the outline is a one-lobe stand-in r(psi) = base + lift (1 + cos psi) / 2 (lobe at
// psi = 0) so that the file opens without femcam; cam and shaft are two separate models in the
// API (no shared nodes), drawn together here (the shaft only when shaft = 1).
SetFactory("Built-in");
DefineConstant[
  base = {10.0, Min 2, Max 200, Step 0.5, Name "Geometry/Base radius (mm)"},
  lift = {10.0, Min 0, Max 100, Step 0.5, Name "Geometry/Lobe lift (mm)"},
  Rb = {6.0, Min 0.5, Max 199, Step 0.1, Name "Geometry/Bore radius Rb (mm)"},
  shaft = {1, Choices{0 = "cam only", 1 = "cam and shaft"}, Name "Geometry/Draw the shaft"},
  n_outline = {720, Min 32, Max 4000, Step 8, Name "Mesh/outline spline points"},
  n_bore = {64, Min 16, Max 1024, Step 4, Name "Mesh/bore vertices (multiple of 4)"},
  h_max_over_web = {0.1, Min 0.02, Max 2, Step 0.01, Name "Mesh/largest element (x web)"},
  growth = {0.1, Min 0.05, Max 1, Step 0.05, Name "Mesh/size growth slope"},
  band = {3, Min 0, Max 10, Step 0.5, Name "Mesh/bore band (x bore spacing)"},
  shaft_h_over_Rs = {0.05, Min 0.01, Max 0.5, Step 0.01, Name "Mesh/shaft element (x Rs)"}
];
web = base - Rb;
If (web <= 0)
  Error("Rb = %g mm must be < the base radius %g mm", Rb, base);
  Abort;
EndIf
// global model: h_max = min(max(h_max_over_web web, 0.07 r_min), Rb / 2)
h_max = h_max_over_web * web;
If (h_max < 0.07 * base)
  h_max = 0.07 * base;
EndIf
If (h_max > 0.5 * Rb)
  h_max = 0.5 * Rb;
EndIf
hb = 2 * Pi * Rb / n_bore;
If (hb > h_max)
  hb = h_max;
EndIf
q = n_bore / 4;
// outline: spline through n_outline points (counter-clockwise)
For i In {0 : n_outline - 1}
  psi = 2 * Pi * i / n_outline;
  r = base + lift * (1 + Cos(psi)) / 2;
  Point(1000 + i) = {r * Cos(psi), r * Sin(psi), 0, h_max};
EndFor
pts[] = {};
For i In {0 : n_outline - 1}
  pts[] += {1000 + i};
EndFor
pts[] += {1000};
Spline(1) = {pts[]};
// bore: quarter arcs from -90 deg about the cam centre
Point(1) = {0, 0, 0, h_max};
Point(11) = {0, -Rb, 0, h_max};
Point(12) = {Rb, 0, 0, h_max};
Point(13) = {0, Rb, 0, h_max};
Point(14) = {-Rb, 0, 0, h_max};
Circle(11) = {11, 1, 12};
Circle(12) = {12, 1, 13};
Circle(13) = {13, 1, 14};
Circle(14) = {14, 1, 11};
Curve Loop(1) = {1};
Curve Loop(2) = {11, 12, 13, 14};
Plane Surface(1) = {1, 2};
Transfinite Curve{11, 12, 13, 14} = q + 1;
Physical Curve("cam_outline") = {1};
Physical Curve("cam_bore") = {11, 12, 13, 14};
Physical Surface("cam") = {1};
If (shaft)
  // line-to-line fit: the shaft radius is the bore radius (the API meshes it as its own model)
  hs = shaft_h_over_Rs * Rb;
  Point(21) = {0, -Rb, 0, hs};
  Point(22) = {Rb, 0, 0, hs};
  Point(23) = {0, Rb, 0, hs};
  Point(24) = {-Rb, 0, 0, hs};
  Circle(21) = {21, 1, 22};
  Circle(22) = {22, 1, 23};
  Circle(23) = {23, 1, 24};
  Circle(24) = {24, 1, 21};
  Curve Loop(3) = {21, 22, 23, 24};
  Plane Surface(2) = {3};
  Transfinite Curve{21, 22, 23, 24} = q + 1;
  Physical Curve("shaft_surface") = {21, 22, 23, 24};
  Physical Surface("shaft") = {2};
EndIf
// size: the bore spacing near the bore, growing with slope growth to h_max
Field[1] = Distance;
Field[1].CurvesList = {11, 12, 13, 14};
Field[1].Sampling = 400;
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = hb;
Field[2].SizeMax = h_max;
Field[2].DistMin = band * hb;
Field[2].DistMax = band * hb + (h_max - hb) / growth;
Background Field = 2;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.Algorithm = 6;
Mesh.ElementOrder = 1;
