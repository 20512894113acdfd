"""Fixtures shared by the atlas tests (the planar and spherical builds)."""

import json
import logging

import numpy as np
import pytest


def _same(a, b):
    assert len(a) == len(b)
    assert np.array_equal(a.signatures, b.signatures)
    assert np.array_equal(a.seeds, b.seeds)
    for name, col in a.linkages.columns().items():
        assert np.array_equal(getattr(b.linkages, name), col), name


def _bump_version(part, key):
    """Rewrite the Parquet `part` with its format version (metadata `key`) one higher."""
    import pyarrow.parquet as pq

    table = pq.read_table(part)
    meta = json.loads(table.schema.metadata[key])
    meta["version"] += 1
    pq.write_table(table.replace_schema_metadata({key: json.dumps(meta).encode()}), part)


@pytest.fixture
def bump_version():
    """Turns an atlas part into one of the next format version (planar or spherical metadata key)."""
    return _bump_version


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
