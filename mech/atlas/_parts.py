"""The block and part machinery that the planar and spherical atlas builds share.

A build runs in blocks whose seeds are a pure function of the build's seed and the block's
index (`block_seed`), so the blocks can be computed here or as tasks of a Dask cluster and
still give the same atlas; each block's rows can be written as one Parquet part of a folder
whose metadata records the block, so a stopped build resumes where it stopped. The planar
and spherical stores pass their own settings readers and checks. pyarrow, tqdm and Dask are
imported only inside the functions that need them.
"""

import json
import os
from contextlib import closing
from pathlib import Path

import numpy as np

from mech._progress import progress_bar
from mech._validate import _show, bool_flag

__all__ = []

#: Blocks kept in flight per worker thread of a Dask cluster.
_AHEAD = 2
#: Schema metadata key of the block record of a part written by a chunked build.
_CHUNK_KEY = b"mech.atlas.chunk"


def block_seed(seed, index):
    """The seed of block `index` of a build with `seed` (NumPy's SeedSequence of the pair)."""
    return int(np.random.SeedSequence([seed, index]).generate_state(1, dtype=np.uint64)[0] >> 1)


def _blocks(start, work, client, build, key=None):
    """Yield ``(index, columns, signatures)`` for blocks start, start + 1, ... in order.

    Without a client each block is computed here when asked for; with one, a window of
    blocks ahead is kept running on the cluster and the results are taken in order.
    `build` computes a block (the planar `build_block` or the spherical `build_sphere_block`)
    and `key(j)` names block j's task (``mech-atlas-block-j`` by default).
    """
    key = (lambda j: f"mech-atlas-block-{j}") if key is None else key
    if client is None:
        index = start
        while True:
            yield (index, *build(*work(index)))
            index += 1
    ahead = max(1, _AHEAD * sum(client.nthreads().values()))
    pending = {}
    index = start
    try:
        while True:
            for j in range(index, index + ahead):
                if j not in pending:
                    pending[j] = client.submit(build, *work(j), pure=False, key=key(j))
            cols, sig = pending.pop(index).result()
            yield index, cols, sig
            index += 1
    finally:
        # blocks not needed: let those in flight end before releasing them (a task
        # cancelled while it runs makes the worker log a warning)
        from distributed import wait

        wait(list(pending.values()))
        pending.clear()


def _take_blocks(blocks, n, total, seed, build, settings, folder, record, write, progress, none_message):
    """Take the blocks of a build in order until `n` rows are kept (the planar and spherical loop).

    `blocks` yields ``(index, columns, signatures)``; `total` rows are already on disk. With a
    `folder` each block's rows are written as a Parquet part by `write` (the
    store's `write_part`), otherwise they are kept. Returns
    ``(kept, sigs, total)``: the kept row records, their signatures and the rows taken in all.
    `none_message(index)` is the ValueError's text when 1000 blocks gave no usable linkage.
    """
    kept, sigs = [], []
    with _bar(progress, n, total) as bar, closing(blocks) as blocks:
        for index, cols, sig in (blocks if total < n else ()):
            take = min(len(sig), n - total)
            rows = record(**{k: v[:take] for k, v in cols.items()})
            if folder is not None and take:
                folder.mkdir(parents=True, exist_ok=True)
                write(folder / f"part-{index:05d}.parquet", rows, sig[:take], np.full(take, seed), settings,
                      chunk={**build, "index": index})
            else:
                kept.append(rows)
                sigs.append(sig[:take])
            total += take
            bar.update(take)
            if total >= n:
                break
            if index > 1000 and total == 0:
                raise ValueError(none_message(index))
    return kept, sigs, total


def read_chunk(part):
    """The chunk record of a part written by a chunked build, or None."""
    import pyarrow.parquet as pq

    meta = pq.read_schema(part).metadata or {}
    return json.loads(meta[_CHUNK_KEY]) if _CHUNK_KEY in meta else None


def _folder(path):
    if not isinstance(path, (str, os.PathLike)) or isinstance(path, bytes):
        raise TypeError(f"Expected `path` to be a folder name, got {_show(path)}")
    return Path(path)


def _read_parts(path, what, version, read_settings, check_settings):
    """The settings and Parquet tables of the atlas folder `path` (planar and spherical `from_parquet`).

    `what` names the atlas in the messages ("an atlas"); `version` is the format version
    expected; every part must have the first part's settings.
    """
    import pyarrow.parquet as pq

    folder = _folder(path)
    parts = sorted(folder.glob("part-*.parquet")) if folder.is_dir() else []
    if not parts:
        raise ValueError(f"Expected `path` to be a folder holding {what}, got {str(path)!r}")
    settings = read_settings(parts[0])
    if settings.get("version") != version:
        raise ValueError(f"Expected {what} of format version {version}, got version "
                         f"{settings.get('version')!r} in {str(path)!r}")
    tables = []
    for part in parts:
        check_settings(settings, read_settings(part), str(part))
        tables.append(pq.read_table(part))
    return settings, tables


def _table_columns(tables, names):
    """The sample columns `names` (kind as str, branch as int8), flat signatures and seeds of `tables`."""
    cols = {name: np.concatenate([t.column(name).to_numpy() for t in tables]) for name in names}
    cols["kind"] = cols["kind"].astype(str)
    cols["branch"] = cols["branch"].astype(np.int8)
    sig = np.concatenate([t.column("signature").combine_chunks().flatten().to_numpy() for t in tables])
    seeds = np.concatenate([t.column("seed").to_numpy() for t in tables])
    return cols, sig, seeds


def _next_part(path, append, settings, read_settings, check_settings):
    """The path of a new part of the atlas folder `path` (planar and spherical `to_parquet`).

    Checks `append` and, when the folder holds parts, that the first has `settings` (read and
    compared with the store's `read_settings` and `check_settings`); creates the folder.
    """
    append = bool_flag("append", append)
    folder = _folder(path)
    parts = sorted(folder.glob("part-*.parquet")) if folder.exists() else []
    if parts and not append:
        raise ValueError(f"Expected `path` without an atlas (or append=True), got {str(path)!r} "
                         f"holding {len(parts)} part(s)")
    if parts:
        check_settings(read_settings(parts[0]), settings, str(path))
    folder.mkdir(parents=True, exist_ok=True)
    # after the last part (a chunked build may leave gaps in the numbers)
    number = max((int(p.stem.split("-")[1]) for p in parts if p.stem.split("-")[1].isdigit()), default=-1) + 1
    return folder / f"part-{number:05d}.parquet"


def _done_parts(folder, settings, build, resume, read_settings, check_settings):
    """The last block index on disk and the rows there, checking that they belong to `build`.

    Shared by the planar and spherical builds; `read_settings` and `check_settings` are the
    store's own.
    """
    parts = sorted(folder.glob("part-*.parquet")) if folder.is_dir() else []
    if not parts:
        return -1, 0
    if not resume:
        raise ValueError(f"Expected `path` without an atlas (or resume=True), got {str(folder)!r} "
                         f"holding {len(parts)} part(s)")
    import pyarrow.parquet as pq

    last, rows = -1, 0
    for part in parts:
        check_settings(read_settings(part), settings, str(part))
        chunk = read_chunk(part)
        if chunk is None or any(chunk.get(k) != v for k, v in build.items()):
            raise ValueError(f"Expected the parts of a build of {build} in `path` to resume, got "
                             f"{chunk!r} in {str(part)!r}")
        last = max(last, int(chunk["index"]))
        rows += pq.read_metadata(part).num_rows
    return last, rows


def _fingerprint(atlas):
    """A digest of the rows of `atlas` (count, settings, a sample of signatures and seeds): an
    index stored beside the Parquet parts belongs to this atlas only if the digests agree."""
    import hashlib

    n = len(atlas)
    step = max(1, n // 65536)
    digest = hashlib.sha256(json.dumps([n, atlas.settings], sort_keys=True).encode())
    for part in (atlas.signatures[::step], atlas.signatures[-1:], atlas.seeds[::step]):
        digest.update(np.ascontiguousarray(part).tobytes())
    return digest.hexdigest()


def _bar(progress, total, initial=0):
    """A bar of the linkages built (`mech._progress.progress_bar`)."""
    return progress_bar(progress, total, initial, desc="atlas", unit="linkage")
