"""A general spherical linkage solver (a crank, then spherical RRR dyads) and the
Stephenson-1, Stephenson-2, Watt-1 and Watt-2 six-bars on the sphere (monograph §2.4)."""

from mech.spherical.linkage._linkage import SphericalLinkage, SphericalLinkagePose
from mech.spherical.linkage._sixbars import stephenson1, stephenson2, stephenson3, watt1, watt2
from mech.spherical.linkage._stephenson3 import SphericalStephenson3

__all__ = ["SphericalLinkage", "SphericalLinkagePose", "stephenson1", "stephenson2", "watt1", "watt2",
           "stephenson3", "SphericalStephenson3"]
