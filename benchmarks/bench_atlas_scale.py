"""Benchmark: a large four-bar atlas built in one process and on a Dask LocalCluster, then indexed
for approximate nearest-neighbour search and queried from a fresh process (issue 28, item 1).

For `n` four-bars (default 10^6):

- build: `build_atlas(n, path=...)` in this process, and again on a `distributed.LocalCluster`
  of 2 worker processes (one thread each), both written as Parquet parts; the rate (linkages
  per second), and the peak resident memory of this process and, for Dask, of this process
  plus its workers (sampled every 0.2 s with psutil); whether the two atlases are identical
  (they must be: each block is a pure function of the seed and its index);
- index: `python -m mech.atlas index` on the Dask atlas (faiss HNSW), its time and size;
- query: in a fresh process that loads the stored atlas and index, the load time and the
  median time of `query` on closed targets (curves of linkages drawn with another seed), once
  through the index and once exact; the recall of the exact nearest signature within the
  index's first 10 answers over 300 such targets.

    python benchmarks/bench_atlas_scale.py                    # 10^6: writes results/atlas_scale.json
    python benchmarks/bench_atlas_scale.py -n 200000 --output /tmp/scale.json
    python benchmarks/bench_atlas_scale.py --skip-single      # the Dask build only

Times are on a shared machine (its load average is recorded). Dask is imported here, never by
``import mech``.
"""

from __future__ import annotations

import argparse
import datetime as _dt
import json
import os
import shutil
import subprocess
import sys
import threading
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(HERE.parent))

from bench_coupler_curve import machine, versions  # noqa: E402

from mech.atlas import Atlas, build_atlas  # noqa: E402


class _PeakMemory:
    """Peak resident memory (bytes) of this process and its child processes, sampled in a thread."""

    def __init__(self, every=0.2):
        import psutil

        self.process, self.every, self.peak, self._stop = psutil.Process(), every, 0, threading.Event()

    def _total(self):
        total = self.process.memory_info().rss
        for child in self.process.children(recursive=True):
            try:
                total += child.memory_info().rss
            except Exception:            # a worker that has just ended
                pass
        return total

    def _run(self):
        while not self._stop.is_set():
            self.peak = max(self.peak, self._total())
            self._stop.wait(self.every)

    def __enter__(self):
        self._thread = threading.Thread(target=self._run, daemon=True)
        self._thread.start()
        return self

    def __exit__(self, *exc):
        self._stop.set()
        self._thread.join()
        self.peak = max(self.peak, self._total())
        return False


def _build(n, folder, client=None, block=16384):
    shutil.rmtree(folder, ignore_errors=True)
    with _PeakMemory() as memory:
        t0 = time.perf_counter()
        build_atlas(n, seed=0, path=folder, client=client, block=block)
        seconds = time.perf_counter() - t0
    return {"seconds": round(seconds, 1), "rate_per_s": round(n / seconds), "peak_memory_mb": round(memory.peak / 2**20)}


def _dask_build(n, folder, workers):
    import logging

    from distributed import Client, LocalCluster

    logging.getLogger("distributed").setLevel(logging.ERROR)
    with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=":0") as cluster, \
            Client(cluster) as client:
        client.run(lambda: __import__("mech.atlas._planar._build"))     # warm the workers (imports)
        out = _build(n, folder, client)
    out["workers"] = workers
    return out


#: run in a fresh process: load the stored atlas and index, time queries, measure recall
_PROBE = r"""
import json, sys, time
import numpy as np
t0 = time.perf_counter()
from mech.atlas import Atlas, query, sample_fourbars
atlas = Atlas.from_parquet(sys.argv[1])
index = atlas._ann
load = time.perf_counter() - t0
from mech.atlas._planar._sampling import coupler_curves
from mech.atlas._planar._signature import _resample_rows, normal_form
s = sample_fourbars(4000, seed=2027)
s = s.take(s.usable)
curves = coupler_curves(s.columns(), 300)
curves = curves[np.all(np.isfinite(curves), axis=1)]
def timed(targets):
    out = []
    for z in targets:
        t = time.perf_counter(); query(atlas, z, k=5); out.append(time.perf_counter() - t)
    return float(np.median(out))
with_index = timed(curves[:60])
atlas.__dict__["_ann"] = None
exact = timed(curves[:60])
forms = normal_form(_resample_rows(curves[:300], atlas.samples, True), atlas.harmonics).candidates
sig, norms = atlas._signatures32
hits = 0
for c in forms:
    c32 = c.astype(np.float32)
    best = int(np.argmin(norms - 2.0 * np.max(sig @ c32.T, axis=1)))
    hits += best in set(index.search(c32, 10).tolist())
print(json.dumps({"rows": len(atlas), "load_s": round(load, 2), "query_median_ms_index": round(1000 * with_index, 1),
                  "query_median_ms_exact": round(1000 * exact, 1), "recall_at_10": hits / len(forms),
                  "recall_targets": len(forms)}))
"""


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("-n", type=int, default=1_000_000)
    parser.add_argument("--folder", default="/tmp/mech-atlas-scale", help="scratch folder for the atlases")
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--skip-single", action="store_true")
    parser.add_argument("--output")
    args = parser.parse_args(argv)
    root = Path(args.folder)
    env = {**os.environ, "PYTHONPATH": str(HERE.parent)}
    report = {"n": args.n}
    if not args.skip_single:
        report["single"] = _build(args.n, root / "single")
        print("single process:", report["single"], flush=True)
    report["dask"] = _dask_build(args.n, root / "dask", args.workers)
    print("dask:", report["dask"], flush=True)
    if not args.skip_single:
        import numpy as np

        a, b = Atlas.from_parquet(root / "single"), Atlas.from_parquet(root / "dask")
        report["identical"] = bool(np.array_equal(a.signatures, b.signatures) and np.array_equal(a.linkages.a, b.linkages.a))
        del a, b
        shutil.rmtree(root / "single", ignore_errors=True)
    t0 = time.perf_counter()
    subprocess.run([sys.executable, "-m", "mech.atlas", "index", str(root / "dask")], check=True, env=env)
    report["index"] = {"seconds": round(time.perf_counter() - t0, 1),
                       "size_mb": round((root / "dask" / "ann" / "hnsw.faiss").stat().st_size / 2**20, 1)}
    print("index:", report["index"], flush=True)
    probe = subprocess.run([sys.executable, "-c", _PROBE, str(root / "dask")], check=True, env=env,
                           capture_output=True, text=True)
    report["fresh_process"] = json.loads(probe.stdout.strip().splitlines()[-1])
    print("fresh process:", report["fresh_process"], flush=True)
    out = {"date": _dt.datetime.now(_dt.timezone.utc).isoformat(timespec="seconds"), "machine": machine(),
           "versions": versions(), "load_average": list(os.getloadavg()), **report}
    path = Path(args.output) if args.output else HERE / "results" / "atlas_scale.json"
    path.write_text(json.dumps(out, indent=1) + "\n")
    print(f"wrote {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
