// femcam contact-region body (the cam; the roller is the same body with R = Rr mirrored to y > 0).
// Same construction as femcam.mesh.mesh_plain_body; defaults from contact_region.toml. Units: mm.
// Open in the gmsh GUI and move the sliders:  gmsh meshes/contact_region.geo
//
// Flat cam (rho = inf): set "flat" = 1 (R is then ignored and the surface is straight; the .geo
// language has no infinity, and k = 1/R cannot draw it). R = 0 has no meaning (femcam refuses
// it) and stops here with an error instead of dividing by zero.
// Differences from the API (femcam/mesh/), on purpose: one body only; the body size is
// L = min(|R|, L_cap) (the API caps the cam at Rr and the roller at domain_over_a * a_ref); the
// fine-zone vertices are not snapped to the exact uniform abscissae (the API moves them by a
// fraction of h onto the arc). The Distance-field sampling is the API's: max(2 n_fine, 100).
SetFactory("Built-in");
DefineConstant[
  R = {20.0, Min -100, Max 100, Step 0.5, Name "Geometry/Surface radius R (mm, <0 concave)"},
  flat = {0, Choices{0 = "curved (radius R)", 1 = "flat (R = inf)"}, Name "Geometry/Flat surface"},
  a_ref = {0.105, Min 0.001, Max 1, Step 0.005, Name "Geometry/Reference half-width a_ref (mm)"},
  L_cap = {10.0, Min 0.5, Max 100, Step 0.5, Name "Geometry/Body size cap (mm)"},
  a_over_h = {20, Min 2, Max 80, Step 1, Name "Mesh/a_ref over h"},
  fine_half_width = {2.5, Min 1.2, Max 10, Step 0.1, Name "Mesh/fine zone half-width (x a_ref)"},
  fine_depth = {0.6, Min 0, Max 5, Step 0.1, Name "Mesh/fine band depth (x a_ref)"},
  growth = {0.3, Min 0.05, Max 1, Step 0.05, Name "Mesh/size growth slope"}
];
If (!flat && R == 0)
  Error("R = 0 is not a surface radius: use flat = 1 for a flat cam (rho = inf)");
  Abort;
EndIf
L = L_cap;
If (!flat && Fabs(R) < L_cap)
  L = Fabs(R);
EndIf
W = 0.9 * L;
h = a_ref / a_over_h;
n_fine = Round(2 * fine_half_width * a_ref / h);
xf = 0.5 * n_fine * h;
lc = L / 8;
k = 0;              // surface curvature 1/R (0: flat)
If (!flat)
  k = 1 / R;
EndIf
// surface y_s(x) = -k x^2 / (1 + sqrt(1 - k^2 x^2))
Point(1) = {-W, -k * W^2 / (1 + Sqrt(1 - k^2 * W^2)), 0, lc};
Point(2) = {-xf, -k * xf^2 / (1 + Sqrt(1 - k^2 * xf^2)), 0, lc};
Point(3) = {xf, -k * xf^2 / (1 + Sqrt(1 - k^2 * xf^2)), 0, lc};
Point(4) = {W, -k * W^2 / (1 + Sqrt(1 - k^2 * W^2)), 0, lc};
Point(6) = {W, -L, 0, lc};
Point(7) = {-W, -L, 0, lc};
If (flat)
  Line(1) = {1, 2};
  Line(2) = {2, 3};
  Line(3) = {3, 4};
Else
  Point(5) = {0, -R, 0, lc};      // arc centre (not meshed; femcam drops it)
  Circle(1) = {1, 5, 2};
  Circle(2) = {2, 5, 3};
  Circle(3) = {3, 5, 4};
EndIf
Line(4) = {4, 6};
Line(5) = {6, 7};
Line(6) = {7, 1};
Curve Loop(1) = {1, 2, 3, 4, 5, 6};
Plane Surface(1) = {1};
Transfinite Curve{2} = n_fine + 1;
Physical Curve("cam_contact") = {1, 2, 3};
Physical Curve("cam_fixed") = {5};
Physical Surface("cam") = {1};
Field[1] = Distance;
Field[1].CurvesList = {2};
Field[1].Sampling = (2 * n_fine > 100) ? 2 * n_fine : 100;   // as femcam.mesh: max(2 n_fine, 100)
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h;
Field[2].SizeMax = lc;
Field[2].DistMin = fine_depth * a_ref;
Field[2].DistMax = fine_depth * a_ref + (lc - h) / growth;
Background Field = 2;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.Algorithm = 6;
Mesh.LcIntegrationPrecision = 1e-7;   // as femcam.mesh
