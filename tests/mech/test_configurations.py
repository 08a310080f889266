"""mech.configurations from Python: rows (a DataFrame with pandas) of sampled configurations."""
from __future__ import annotations

import pytest

from mech.configurations import configurations


def test_rows_without_pandas():
    rows = configurations("ground O A 5; bar O B 2; bar B C 5; bar C A 4", 8, frame=False)
    assert len(rows) >= 6 and {r["circuit"] for r in rows} == {1, 2}
    r = rows[0]
    assert r.keys() >= {"mode", "circuit", "c1", "s1", "theta1", "joint_O", "B_x", "C_y"}
    assert abs(r["c1"] ** 2 + r["s1"] ** 2 - 1) < 1e-9


def test_data_frame():
    pandas = pytest.importorskip("pandas")
    df = configurations("ground O A 5; bar O B 2; bar B C 5; bar C A 4", 8)
    assert isinstance(df, pandas.DataFrame) and list(df.columns[:3]) == ["mode", "circuit", "c1"]
