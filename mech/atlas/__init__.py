"""A searchable atlas of coupler curves: which four-bars trace a curve like this one (issue 13).

Layers, each usable alone:

- shape signatures (`curve_signature`, `resample`, `read_points`; a target read from a CSV
  or from a path drawn in an SVG editor by `read_target`, `read_svg`): a fixed-length vector
  that does not depend on where a curve lies, its size, its turn, its start or its direction
  (derivation page :ref:`deriv-shape-signature`);
- a sampled design space of planar four-bars (`sample_fourbars`, `FourBarSamples`) with
  the Grashof type, assembly branch, input range and minimum transmission angle of each,
  and one of slider-cranks with a coupler point on the rod (`sample_slider_cranks`,
  `SliderCrankSamples`; ``build_atlas(..., mechanism="slider-crank")``, searched by the
  same `query`, whose matches then carry a `PlacedSliderCrank` and its one cognate
  slider-crank);
- the atlas itself (`build_atlas`, `Atlas`, stored as Parquet through pyarrow) and its
  search (`query`, returning `Match` records placed on the target, with the two
  Roberts-Chebyshev cognates of each match; an open arc is matched against parts of
  the closed curves), `refine`, which improves a match by constrained optimisation on the
  real curve error (an open match as an open arc), and `find_linkages`, which refines the
  best few matches and their cognates and keeps the best that satisfy the `Constraints` (by
  default a crank that turns fully, a transmission angle of at least 30 degrees, links
  within a ratio of 10);
- builds in blocks (`build_atlas`), on a Dask cluster if asked, written part by part to a
  folder and resumable; the index of open-arc windows is stored in that folder on first use;
- an approximate nearest-neighbour index of the signatures (faiss's HNSW graph, optional),
  built by ``python -m mech.atlas index ATLAS_DIR`` and stored in the folder; a new process
  that loads the atlas loads it and searches through it, else the search is exact;
- on the sphere: `sphere_signature` (invariant to rotations of the sphere, start and
  direction; :ref:`deriv-sphere-signature`), `sample_sphere_fourbars` (full-turn and
  rocking inputs, type, branch, minimum transmission angle), `build_sphere_atlas` (blocks,
  Dask, Parquet, resumable), `SphereAtlas`, `query_sphere` (closed curves and open arcs),
  `refine_sphere` and `find_sphere_linkages`.

The code is grouped by subject: ``mech/atlas/_planar/`` holds the planar atlas (sampling,
signatures, store, build, search, open arcs, constraints, refinement, multistart),
``mech/atlas/_sphere/`` the spherical one, and the two modules they share sit beside them
(``_records``: the sample records; ``_parts``: blocks, seeds and Parquet parts of a build).

``import mech.atlas`` loads NumPy only: pyarrow is imported when an atlas is saved or
loaded, tqdm when a build shows a progress bar, Dask only by the code that makes a client.
"""

from mech.atlas._planar._signature import curve_signature, read_points, resample
from mech.atlas._target import read_svg, read_target
from mech.atlas._planar._sampling import FourBarSamples, sample_fourbars
from mech.atlas._planar._store import ATLAS_VERSION, Atlas
from mech.atlas._planar._build import build_atlas
from mech.atlas._planar._search import Match, PlacedLinkage, PlacedSliderCrank, query
from mech.atlas._planar._constraints import Constraints
from mech.atlas._planar._refine import refine
from mech.atlas._planar._slider import SliderCrankSamples, sample_slider_cranks
from mech.atlas._planar._multistart import find_linkages
from mech.atlas._sphere._signature import sphere_signature
from mech.atlas._sphere._sampling import SphereSamples, sample_sphere_fourbars
from mech.atlas._sphere._store import SPHERE_ATLAS_VERSION, SphereAtlas
from mech.atlas._sphere._build import build_sphere_atlas
from mech.atlas._sphere._fit import SphereMatch
from mech.atlas._sphere._search import find_sphere_linkages, query_sphere, refine_sphere

__all__ = [
    "ATLAS_VERSION",
    "Atlas",
    "Constraints",
    "FourBarSamples",
    "Match",
    "PlacedLinkage",
    "PlacedSliderCrank",
    "SPHERE_ATLAS_VERSION",
    "SliderCrankSamples",
    "SphereAtlas",
    "SphereMatch",
    "SphereSamples",
    "build_atlas",
    "build_sphere_atlas",
    "curve_signature",
    "find_linkages",
    "find_sphere_linkages",
    "query",
    "query_sphere",
    "read_points",
    "read_svg",
    "read_target",
    "refine",
    "refine_sphere",
    "resample",
    "sample_fourbars",
    "sample_slider_cranks",
    "sample_sphere_fourbars",
    "sphere_signature",
]
