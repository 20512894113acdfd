"""Evaluate functions of a generated JavaScript module under Node, on arrays of points.

The points go to Node and the results come back as raw float64 files (exact, NaN and
infinities included), so a comparison with the NumPy backend sees every bit. Used by the
generator's numeric check and by ``tests/generated/test_js_kernels.py``.
"""

from __future__ import annotations

import json
import shutil
import subprocess
import tempfile
from pathlib import Path

import numpy as np

__all__ = ["node", "evaluate"]

# reads a job list on stdin; for each job, calls the function once per point
_RUNNER = r"""
import { readFileSync, writeFileSync } from "node:fs";
import { pathToFileURL } from "node:url";
const jobs = JSON.parse(readFileSync(0, "utf8"));
const modules = new Map();
for (const job of jobs) {
  if (!modules.has(job.module)) modules.set(job.module, await import(pathToFileURL(job.module).href));
  const fn = modules.get(job.module)[job.name];
  const buf = readFileSync(job.input);
  const x = new Float64Array(buf.buffer, buf.byteOffset, buf.byteLength / 8);
  const n = job.n, k = job.nargs, m = job.nout;
  const y = new Float64Array(n * m);
  const args = new Array(k);
  for (let i = 0; i < n; i++) {
    for (let j = 0; j < k; j++) args[j] = x[j * n + i];
    const r = fn(...args);
    if (m === 1) y[i] = r;
    else for (let j = 0; j < m; j++) y[j * n + i] = r[j];
  }
  writeFileSync(job.output, Buffer.from(y.buffer));
}
"""


def node():
    """The path of ``node``, or None."""
    return shutil.which("node") or shutil.which("nodejs")


def evaluate(calls, timeout=600):
    """Run JavaScript functions on arrays of points.

    ``calls``: a list of ``(module_path, function_name, args, n_outputs)``, ``args`` a
    sequence of 1-D float arrays of one length n (one per argument). Returns, per call, an
    array of shape ``(n_outputs, n)``.
    """
    exe = node()
    if exe is None:
        raise RuntimeError("node is not installed (Debian: apt-get install nodejs)")
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        (tmp / "runner.mjs").write_text(_RUNNER)
        jobs = []
        for k, (module, name, args, nout) in enumerate(calls):
            x = np.ascontiguousarray(np.stack([np.asarray(a, dtype=float) for a in args]) if args
                                     else np.empty((0, 0)))
            n = x.shape[1] if args else 0
            x.astype("<f8").tofile(tmp / f"in{k}.bin")
            jobs.append({"module": str(Path(module).resolve()), "name": name, "n": n,
                         "nargs": len(args), "nout": nout,
                         "input": str(tmp / f"in{k}.bin"), "output": str(tmp / f"out{k}.bin")})
        done = subprocess.run([exe, str(tmp / "runner.mjs")], input=json.dumps(jobs), text=True,
                              timeout=timeout, capture_output=True)
        if done.returncode != 0:
            raise RuntimeError(f"node failed: {done.stderr.strip()}")
        return [np.fromfile(tmp / f"out{k}.bin", dtype="<f8").reshape(job["nout"], job["n"])
                for k, job in enumerate(jobs)]
