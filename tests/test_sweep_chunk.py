"""The typed chunk table (:class:`femcam.sweep.chunk.ChunkRows`): only declared columns can be
written, and a provider's declared column goes through the chunk store and the table builder to
the CSV under its CSV name and unit."""

from __future__ import annotations

import pickle

import numpy as np
import pytest

from femcam.io import read_csv, write_csv
from femcam.sweep.chunk import PROVIDER_NUMERIC, PROVIDER_TEXT, ChunkRows
from femcam.sweep.extras import ERROR_COLUMN, PROVIDERS
from femcam.sweep.store import ChunkStore
from femcam.sweep.table import COLUMNS, NUMERIC, TEXT_COLUMNS, TableBuilder

HS = next(p for p in PROVIDERS if p.name == "halfspace")
P_AXIAL = next(c for c in HS.columns if c.si == "hs_p_axial_peak")   # csv p_axial_peak_MPa


def test_undeclared_column_write_raises():
    rows = ChunkRows(3)
    with pytest.raises(AttributeError, match="p0_fee"):
        rows.p0_fee = np.zeros(3)                      # misspelt sweep column
    name = "hs_p_axial_peek"                           # misspelt provider column, set by name
    with pytest.raises(AttributeError, match=name):
        setattr(rows, name, np.zeros(3))
    with pytest.raises(AttributeError, match="no column"):
        rows.anything_else = np.zeros(3)
    with pytest.raises(ValueError, match="3 rows"):
        rows.p0_fe = np.zeros(2)                       # a whole column of the wrong length
    with pytest.raises(KeyError, match="nonsense"):
        rows.get("nonsense")
    assert not any(name.startswith(("p0_fee", "anything")) for name in rows.columns())


def test_sweep_columns_exist_provider_columns_once_set():
    rows = ChunkRows(2)
    assert rows.columns() == NUMERIC + TEXT_COLUMNS
    assert np.isnan(rows.p0_fe).all() and list(rows.status) == ["", ""]
    assert "hs_p_axial_peak" not in rows and rows.get("hs_p_axial_peak", 7) == 7
    with pytest.raises(AttributeError, match="not computed"):
        _ = rows.hs_p_axial_peak
    rows.extras_error = np.array(["", ""], dtype=object)
    setattr(rows, P_AXIAL.si, np.array([1.5e9, np.nan]))
    assert rows.columns()[-2:] == (ERROR_COLUMN, P_AXIAL.si)   # in the order set
    assert rows.is_text(ERROR_COLUMN) and not rows.is_text(P_AXIAL.si)
    assert set(PROVIDER_NUMERIC) >= {c.si for p in PROVIDERS for c in p.columns}
    assert set(PROVIDER_TEXT) >= {t for p in PROVIDERS for t in p.text}


def test_pickle_keeps_columns_order_and_ring_error():
    rows = ChunkRows(2)
    rows.p0_fe[0] = 1e9
    setattr(rows, P_AXIAL.si, np.array([1.0, 2.0]))
    rows.ring_error = ValueError("refused")
    back = pickle.loads(pickle.dumps(rows))
    assert back.columns() == rows.columns()
    assert back.p0_fe[0] == 1e9 and back.hs_p_axial_peak.tolist() == [1.0, 2.0]
    assert str(back.ring_error) == "refused"


def test_provider_column_round_trips_to_the_csv(tmp_path):
    """A provider column set in a chunk (SI, Pa) reaches the CSV in its CSV unit (MPa: 1.5e9 Pa
    is 1500 MPa), after the chunk store's file and the table builder, with the sweep's own
    columns first and the provider's after them; text likewise."""
    bounds = [(0, 2), (2, 3)]
    store = ChunkStore(tmp_path / "chunks", {"n": 3}, bounds)
    store.open(resume=False)
    builder = TableBuilder(bounds)
    p_pa = [1.5e9, 2.25e9, np.nan]
    for c, (a, b) in enumerate(bounds):
        rows = ChunkRows(b - a)
        rows.theta[:] = np.radians([10.0, 20.0, 30.0][a:b])
        rows.status[:] = "ok"
        setattr(rows, P_AXIAL.si, np.array(p_pa[a:b]))
        rows.hs_flags = np.array(["edge", ""][: b - a], dtype=object)
        store.write(c, rows)
        builder.put(c, store.load(c))      # the resume path: the chunk read back from its file
    table = builder.table()
    path = write_csv(tmp_path / "sweep.csv", table, {}, columns=COLUMNS + (P_AXIAL,),
                     text_columns=TEXT_COLUMNS + ("hs_flags",))
    cols, _ = read_csv(path)
    names = list(cols)
    assert names[:len(COLUMNS)] == [c.csv for c in COLUMNS]
    assert names[len(COLUMNS)] == "p_axial_peak_MPa" == P_AXIAL.csv
    np.testing.assert_allclose(cols["p_axial_peak_MPa"][:2], [1500.0, 2250.0], rtol=1e-12)
    assert np.isnan(cols["p_axial_peak_MPa"][2])
    np.testing.assert_allclose(cols["theta_deg"], [10.0, 20.0, 30.0], rtol=1e-12)
    assert list(cols["hs_flags"][:2]) == ["edge", ""]
