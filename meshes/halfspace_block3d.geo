// Quarter block of the 3D FE reference for the finite-length half-space contact
// (benchmarks/bench_halfspace_fe3d_gmsh.py; defaults from halfspace_block3d.toml). Units: mm.
// Open in the gmsh GUI and move the sliders:  gmsh meshes/halfspace_block3d.geo
// x rolling direction (symmetry plane x = 0), y axial (symmetry plane y = 0, the roller end at
// y = L/2), z normal (contact face z = 0, bottom z = -depth fixed). The top face is split at the
// contact strip 0 <= x <= strip_over_b b, 0 <= y <= L/2 (the contact candidate nodes).
// Mesh size: a cascade of Box fields, h + growth * distance from the strip, and a finer box
// over the last end_band mm of the strip (the roller end).
SetFactory("OpenCASCADE");
DefineConstant[
  b = {0.091, Min 0.01, Max 1, Step 0.001, Name "Geometry/Hertz half-width b (mm)"},
  Lh = {5.0, Min 0.5, Max 50, Step 0.5, Name "Geometry/half loaded length L/2 (mm)"},
  ext = {0.0, Min 0, Max 20, Step 0.5, Name "Geometry/block continues past the end by (mm)"},
  X = {10.0, Min 1, Max 50, Step 1, Name "Geometry/side (mm)"},
  D = {10.0, Min 1, Max 50, Step 1, Name "Geometry/depth (mm)"},
  sb = {2.0, Min 1, Max 5, Step 0.1, Name "Geometry/strip width (x b)"},
  hc = {0.30, Min 0.05, Max 2, Step 0.01, Name "Mesh/strip size (x b)"},
  he = {0.22, Min 0.05, Max 2, Step 0.01, Name "Mesh/end size (x b)"},
  band = {0.3, Min 0.05, Max 2, Step 0.05, Name "Mesh/end band (mm)"},
  g = {0.45, Min 0.1, Max 1, Step 0.05, Name "Mesh/growth"},
  hmax = {2.0, Min 0.1, Max 10, Step 0.1, Name "Mesh/max size (mm)"}
];
Box(1) = {0, 0, -D, X, Lh + ext, D};
Rectangle(100) = {0, 0, 0, sb * b, Lh};
v() = BooleanFragments{ Volume{1}; Delete; }{ Surface{100}; Delete; };
Physical Volume("block") = {v()};
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.Algorithm3D = 1;
// cascade: box k = strip grown by d_k = 2^k b in x, y (past the end) and z, size hc b + g d_k
For k In {0:9}
  d = (k == 0) ? 0 : 2^(k-1) * b;
  Field[k + 1] = Box;
  Field[k + 1].VIn = hc * b + g * d;
  Field[k + 1].VOut = hmax;
  Field[k + 1].XMin = -1; Field[k + 1].XMax = sb * b + d;
  Field[k + 1].YMin = -1; Field[k + 1].YMax = Lh + d;
  Field[k + 1].ZMin = -b - d; Field[k + 1].ZMax = 1;
  Field[k + 1].Thickness = d + b;
EndFor
Field[20] = Box;
Field[20].VIn = he * b; Field[20].VOut = hmax;
Field[20].XMin = -1; Field[20].XMax = sb * b;
Field[20].YMin = Lh - band; Field[20].YMax = Lh + band;
Field[20].ZMin = -b; Field[20].ZMax = 1;
Field[20].Thickness = b;
Field[30] = Min;
Field[30].FieldsList = {1:10, 20};
Background Field = 30;
