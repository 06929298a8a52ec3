"""WearMap after ``cycles`` revolutions on coated bodies: the deepest point's position and the
worn volume come from the same depth totals as ``max_depth``.

References, written in the tests: the coating wear law (Archard 1953, linear in k; docs/sweep.md
"Coating wear coefficient")

    h(N) = min(N d_c, t) + max(N - t/d_c, 0) d_s,        d_c = r d_s,  r = k_c / k_s,

and Archard's volume ``V = k sum F v_slip dt`` per revolution (``WearMap.volume_archard``,
conserved by the map to ``conservation_error``). With a uniform thickness ``t``, h(N) is a
strictly increasing function of ``d_s`` (slope ``N r`` while the coating lasts, ``N`` after), so
the deepest point after N revolutions is the deepest point of one revolution; it moves only when
the thickness varies along the surface, which is the case built here.
"""

from __future__ import annotations

import dataclasses
import inspect
import re

import numpy as np
import pytest

from femcam.scene import contact_case, load_scene
from femcam.wear import map as wear_map_module
from femcam.wear.coating import coating_wear
from femcam.wear.options import wear_coefficient_info
from femcam.wear.scene import scene_wear

SCENE = "examples/seed002_study_model.toml"
TH = np.radians(np.arange(0.0, 360.0, 2.0))
COAT = """
[materials.{body}.coating]
thickness_um = {t}
E_GPa = 170.0
nu = 0.22
wear_k_mm3_per_N_m = {k_mm3}
"""


def _coating(scene):
    """The scene's coating wear data (its layers, [wear] settings and cam hardness)."""
    return coating_wear(scene.layers, scene.wear, scene.cam.hardness)


def _wear_of(scene):
    """The arguments of wear_coefficient_info: the scene's [wear] record and cam hardness (Pa)."""
    return scene.wear, scene.cam.hardness


def _coated(tmp_path, body, t_um, k_mm3):
    p = tmp_path / f"coated_{body}.toml"
    p.write_text(open(SCENE).read() + COAT.format(body=body, t=t_um, k_mm3=k_mm3))
    return load_scene(p)


def _layered(d_s, r, t, N):
    """h(N) written out per point: N d_c while N d_c <= t, then t + (N - t/d_c) d_s."""
    return np.array([N * r * ds if N * r * ds <= tt else tt + (N - tt / (r * ds)) * ds
                     for ds, tt in zip(d_s, np.broadcast_to(t, d_s.shape), strict=True)])


def _window(x, centre, period, half):
    """Points within ``half`` of ``centre`` on a periodic coordinate."""
    return np.abs((x - centre + period / 2) % period - period / 2) < half


def test_deepest_point_after_cycles_is_where_the_coating_wore_through():
    # thick coating (intact after N) on the half of the surface around the one-revolution deepest
    # point x1, thin coating (worn through) on the other half: the deepest point after N is the
    # deepest one-revolution point of the thin half (its h = t2 (1 - 1/r) + N d2 = 0.55 N d2 beats
    # the intact half's h <= N r d1 = 0.1 N d1 since d2 > d1 / 5.5 here)
    N, r = 1e9, 0.1
    plain = load_scene(SCENE)
    bare, _, _ = scene_wear(contact_case(plain, TH), cycles=N, coating=_coating(plain))
    for x, d_s, period, field in (
            (bare.x_cam, bare.depth_cam, bare.perimeter, "depth_cam_cycles"),
            (bare.x_follower, bare.depth_follower_total / N, bare.follower_period, "depth_follower_cycles")):
        x1 = x[np.argmax(d_s)]
        thick = _window(x, x1, period, period / 4)
        d2 = d_s[~thick].max()
        x2 = x[~thick][np.argmax(d_s[~thick])]
        t = np.where(thick, 2.0 * N * r * d_s.max(), 0.5 * N * r * d2)
        h = _layered(d_s, r, t, N)
        assert np.all(N * r * d_s[thick] < t[thick]) and N * r * d2 > t[~thick][0]   # the construction
        assert not _window(np.array([x2]), x1, period, period / 4)[0]
        wm = dataclasses.replace(bare, **{field: h})
        if field == "depth_cam_cycles":
            assert wm.max_depth == pytest.approx(0.5 * N * r * d2 * (1 - 1 / r) + N * d2, rel=1e-12)
            assert wm.x_max == x2
            # the contact of the reported angle is within one angle step of the deepest point
            step = np.max(np.diff(np.append(bare.xi_cam, bare.perimeter)))
            gap = abs((bare.xi_cam[wm.i_max] - x2 + period / 2) % period - period / 2)
            assert gap <= step
            assert wm.theta_max == bare.theta[wm.i_max]
        else:
            assert wm.max_depth_follower == pytest.approx(0.5 * N * r * d2 * (1 - 1 / r) + N * d2, rel=1e-12)
            assert wm.x_max_follower == x2


def test_uniform_coating_keeps_the_deepest_point(tmp_path):
    # the hard case: a uniform coating worn through at the deepest points but not elsewhere does
    # not move the deepest point (h(N) increases with d_s), and position and depth agree
    k_s = wear_coefficient_info(*_wear_of(load_scene(SCENE)))[0]
    scene = _coated(tmp_path, "cam", 2.0, 5e-10)
    r = 5e-19 / k_s
    plain = load_scene(SCENE)
    one, _, _ = scene_wear(contact_case(plain, TH), cycles=1.0, coating=_coating(plain))
    N = 2e-6 / (r * np.median(one.depth_cam))
    wm, _, _ = scene_wear(contact_case(scene, TH), cycles=N, coating=_coating(scene))
    h = _layered(one.depth_cam, r, 2e-6, N)
    assert np.any(h < 2e-6) and np.any(h > 2e-6)
    assert wm.x_max == one.x_cam[np.argmax(h)] == one.x_cam[np.argmax(one.depth_cam)]
    assert wm.max_depth == pytest.approx(h.max(), rel=1e-12)
    assert wm.i_max == one.i_max


@pytest.mark.parametrize("body", ["cam", "roller"])
def test_summary_volume_after_cycles_uses_the_coating(tmp_path, body):
    # soft coating k_c = 2 k_s, t = 1 um: intact after 1e7 revolutions (V = r N V_s), worn through
    # everywhere after 1e8 (V = l S t (1 - 1/r) + N V_s, S the worn surface's length); V_s is
    # Archard's k sum F v_slip dt per revolution. rtol 1e-5: the map conserves Archard's volume to
    # its conservation_error (2.7e-6 at 2 degree steps, measured), not to round-off.
    k_s = wear_coefficient_info(*_wear_of(load_scene(SCENE)))[0]
    r = 1e-17 / k_s
    scene = _coated(tmp_path, body, 1.0, 1e-8)
    for N in (1e7, 1e8):
        wm, _, _ = scene_wear(contact_case(scene, TH), cycles=N, coating=_coating(scene))
        V_s = wm.volume_archard
        S = wm.perimeter if body == "cam" else wm.follower_period
        depth = wm.depth_cam_total if body == "cam" else wm.depth_follower_total
        key = "volume_cam_m3" if body == "cam" else "volume_follower_m3"
        if N == 1e7:
            assert np.all(depth < 1e-6)
            ref = r * N * V_s
        else:
            assert np.all(depth > 1e-6)
            ref = wm.length * S * 1e-6 * (1 - 1 / r) + N * V_s
        assert wm.summary()[key] == pytest.approx(ref, rel=1e-5)
        other = "volume_follower_m3" if body == "cam" else "volume_cam_m3"
        assert wm.summary()[other] == pytest.approx(N * V_s, rel=1e-5)   # the uncoated body


def test_k_factor_source_is_cited_once():
    # the docstring and the code comment of wear_map name the same producer of k_factor, and it
    # exists and returns k(lambda)/k
    from femcam import assess
    src = inspect.getsource(wear_map_module)
    doc = wear_map_module.wear_map.__doc__
    cited = set(re.findall(r"femcam\.[\w.]+", doc[doc.index("k_factor :"):doc.index("regime :")]))
    cited |= set(re.findall(r"k_factor is not None:.*\((femcam\.[\w.]+)\)", src))
    cited |= set(re.findall(r"k\(lambda\)/k, (femcam\.[\w.]+)\)", src))
    assert cited == {"femcam.assess.wear_factor"}
    assert "k(lambda) / k" in assess.wear_factor.__doc__


def test_cli_wear_map_writes_the_coated_totals(tmp_path, capsys):
    # the CLI's files after N revolutions use the coating too: a soft cam coating (k_c = 2 k_s,
    # t = 1 um) worn through everywhere after 1e8 revolutions has the closed-form volume
    # l S t (1 - 1/r) + N V_s (as above), and every depth after N in the surface CSV is
    # t + (N - t / d_c) d_s of its own per-revolution depth d_s (the layered law, written out).
    from femcam.cli import main

    k_s = wear_coefficient_info(*_wear_of(load_scene(SCENE)))[0]
    r = 1e-17 / k_s
    p = tmp_path / "coated_cam.toml"
    p.write_text(open(SCENE).read() + COAT.format(body="cam", t=1.0, k_mm3=1e-8))
    N = 1e8
    out = tmp_path / "out"
    assert main(["wear", "map", str(p), "--out", str(out), "--step-deg", "2", "--cycles", f"{N:g}",
                 "--no-plots"]) == 0
    capsys.readouterr()
    summ = (out / "wear_summary.csv").read_text().splitlines()
    vals = dict(zip(summ[0].split(","), summ[1].split(","), strict=True))
    S, V_s = None, float(vals["volume_archard_mm3"]) * 1e-9 / N
    surf = [row.split(",") for row in (out / "wear_scene_surface.csv").read_text().splitlines()
            if row[:1].isdigit() or row[:1] == "-"]
    x = np.array([float(c[0]) for c in surf]) * 1e-3
    d_s = np.array([float(c[1]) for c in surf]) * 1e-9
    hN = np.array([float(c[2]) for c in surf]) * 1e-6
    ref = _layered(d_s, r, 1e-6, N)
    assert np.allclose(hN, ref, rtol=1e-5, atol=1e-12)       # CSV keeps 6 significant digits
    S = x[-1] - x[0] + (x[1] - x[0])                          # the perimeter of the uniform grid
    scene = load_scene(p)
    length = scene.length
    assert float(vals["volume_cam_mm3"]) * 1e-9 == pytest.approx(
        length * S * 1e-6 * (1 - 1 / r) + N * V_s, rel=1e-4)   # CSV volumes keep 6 digits; the
    # perimeter S is rebuilt here from the rounded arc column (1e-5 of x), hence 1e-4
