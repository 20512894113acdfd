"""An approximate nearest-neighbour index of an atlas's signatures, stored beside its Parquet parts.

The exact signature stage of `query` streams every signature of the atlas once per query
(about 10 ms per million rows here); at ten million rows that is most of a query's time. A
graph index (HNSW, from faiss, an optional dependency) finds the nearest signatures by
walking a small-world graph instead, in well under a millisecond, at the price of sometimes
missing one. The index is built once (`build_index`, or ``python -m mech.atlas index``),
written into the atlas folder as ``ann/hnsw.faiss`` with the atlas's fingerprint, and read,
not rebuilt, by the next process that loads the atlas. Without faiss, or without a stored
index, `query` runs the exact search, with the same results.

The search asks the index for the nearest rows of each of the target's four normal forms
(the nearest form is the one that matters, :ref:`deriv-shape-signature`), merges them, and
ranks the merged rows by their exact distance, so only the short list's membership is
approximate. The graph's breadth at search time, `EF_SEARCH`, was chosen by measuring the
recall of the exact nearest row (``benchmarks/bench_atlas.py --ann``).
"""

import json
import os
from pathlib import Path

import numpy as np

from mech.atlas._parts import _fingerprint

__all__ = []

#: Folder and file names of the stored index inside an atlas folder.
ANN_FOLDER = "ann"
ANN_FILE = "hnsw.faiss"
#: Neighbours per node of the HNSW graph, and the breadth of its construction.
NEIGHBOURS = 32
EF_CONSTRUCTION = 80
#: Breadth of the graph search (at least the number of rows asked for).
EF_SEARCH = 96


def faiss_module():
    """faiss if it is installed, else None (the exact search is then used)."""
    try:
        import faiss
    except ImportError:
        return None
    return faiss


class SignatureIndex:
    """An HNSW index of signature rows (float32, L2) and the fingerprint of the atlas it indexes."""

    def __init__(self, index, fingerprint):
        self.index = index
        self.fingerprint = fingerprint

    def __len__(self):
        return int(self.index.ntotal)

    def search(self, candidates, m):
        """Rows among the `m` nearest of any of `candidates` (c, D), merged, in no order."""
        import faiss

        self.index.hnsw.efSearch = max(EF_SEARCH, m)
        # one thread: four short walks cost less than waking OpenMP's threads (and much less
        # on a loaded machine, where those threads spin waiting for a core)
        threads = faiss.omp_get_max_threads()
        faiss.omp_set_num_threads(1)
        try:
            _, rows = self.index.search(np.ascontiguousarray(candidates, dtype=np.float32), m)
        finally:
            faiss.omp_set_num_threads(threads)
        return np.unique(rows[rows >= 0])


def build_index(atlas, *, save=True):
    """Build the HNSW index of `atlas`'s signatures, keep it with the atlas, and store it in the
    atlas folder (if the atlas was read from one and `save`). Needs faiss; returns the index."""
    faiss = faiss_module()
    if faiss is None:
        raise ImportError("Expected faiss (pip install faiss-cpu) to build an approximate index, got none installed")
    sig, _ = atlas._signatures32
    index = faiss.IndexHNSWFlat(sig.shape[1], NEIGHBOURS)
    index.hnsw.efConstruction = EF_CONSTRUCTION
    index.add(sig)
    found = SignatureIndex(index, _fingerprint(atlas))
    atlas.__dict__["_ann"] = found                  # the cached_property's slot
    if save and atlas.path is not None:
        _save(atlas, found)
    return found


def load_index(atlas):
    """The stored index of an atlas read from a folder, or None (no faiss, none stored, or
    stored for other rows)."""
    faiss = faiss_module()
    if faiss is None or atlas.path is None:
        return None
    folder = Path(atlas.path) / ANN_FOLDER
    try:
        meta = json.loads((folder / (ANN_FILE + ".json")).read_text())
    except (OSError, ValueError):
        return None
    fingerprint = _fingerprint(atlas)
    if meta.get("fingerprint") != fingerprint or meta.get("rows") != len(atlas):
        return None
    try:
        index = faiss.read_index(str(folder / ANN_FILE))
    except RuntimeError:                       # unreadable or half-written: the exact search
        return None
    return SignatureIndex(index, fingerprint) if index.ntotal == len(atlas) else None


def _save(atlas, found):
    """Write the index and its fingerprint atomically (skipped where the folder is read-only)."""
    import faiss

    folder = Path(atlas.path) / ANN_FOLDER
    try:
        folder.mkdir(exist_ok=True)
        scratch = folder / (ANN_FILE + ".partial")
        faiss.write_index(found.index, str(scratch))
        os.replace(scratch, folder / ANN_FILE)
        meta = {"rows": len(atlas), "fingerprint": found.fingerprint, "neighbours": NEIGHBOURS,
                "ef_construction": EF_CONSTRUCTION, "faiss": faiss.__version__}
        (folder / (ANN_FILE + ".json")).write_text(json.dumps(meta))
    except OSError:
        return None
    return folder / ANN_FILE
