"""Fixtures shared by the atlas tests (the planar and spherical builds)."""

import logging

import numpy as np
import pytest


def _same(a, b):
    assert len(a) == len(b)
    assert np.array_equal(a.signatures, b.signatures)
    assert np.array_equal(a.seeds, b.seeds)
    for name, col in a.linkages.columns().items():
        assert np.array_equal(getattr(b.linkages, name), col), name


@pytest.fixture
def same_atlas():
    """A check that two atlases (planar or spherical) are equal bit for bit: rows, seeds, columns."""
    return _same


@pytest.fixture(scope="module")
def client():
    """A local Dask cluster of two single-thread workers, one per test module."""
    distributed = pytest.importorskip("distributed")
    logging.getLogger("distributed").setLevel(logging.ERROR)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=False,
                                  dashboard_address=":0") as cluster, distributed.Client(cluster) as c:
        yield c
