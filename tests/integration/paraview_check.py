"""Opens grainbridge's XDMF sidecars in ParaView and checks what a user would see.

Run by pvpython (Debian: python3-paraview) through RunParaviewCheck.cmake, after
write_sample_outputs has written a known particle output and field output together with
expected.json:

    pvpython paraview_check.py <output folder>/expected.json

Reader: paraview.simple.XDMFReader (vtkXdmfReader, XDMF 2), the one ParaView 5.11 offers
for .xmf that gets our files right. Checked against 5.11.0: Xdmf3ReaderS folds the
particles and contacts grids of a spatial collection into one multipiece dataset, and both
Xdmf3 readers build a Polyvertex grid without connectivity as points with zero cells, so
the particles would not render in the default Surface representation. XDMFReader gives one
vertex cell per particle and a named block per grid.

Checks, per time step: the time values are the frame times; the particles block has N
points (and N vertex cells) and the known radius values; the contacts block is there
exactly when the frame has contacts, with M line cells over 2M points, short segments (a
contact across the periodic box is not drawn across it) and its force arrays; the field
grid has nx*ny*nz cells, the known bounds, every array, and ep_g in [k][j][i] order.
"""
import json
import os
import re
import sys
import xml.etree.ElementTree as ET

from paraview import servermanager
from paraview.simple import Delete, XDMFReader

errors = []


def check(condition, message):
    if not condition:
        errors.append(message)
    return condition


def leaves(data, name=None):
    """(block name, dataset) for every leaf of a possibly nested multiblock.

    The XDMF reader returns a temporal collection of spatial collections as a multiblock
    whose blocks are the grids of the current step. Grid names repeat over steps, so it
    suffixes them ("particles[1]"); the suffix is dropped here.
    """
    if data is None:
        return []
    if data.IsA("vtkMultiBlockDataSet") or data.IsA("vtkMultiPieceDataSet"):
        out = []
        for b in range(data.GetNumberOfBlocks() if data.IsA("vtkMultiBlockDataSet") else data.GetNumberOfPieces()):
            child = data.GetBlock(b) if data.IsA("vtkMultiBlockDataSet") else data.GetPiece(b)
            child_name = name
            if data.HasMetaData(b) and data.GetMetaData(b).Has(data.NAME()):
                child_name = re.sub(r"\[\d+\]$", "", data.GetMetaData(b).Get(data.NAME()))
            out.extend(leaves(child, child_name))
        return out
    return [(name, data)]


def array_values(arrays, name):
    a = arrays.GetArray(name)
    if a is None:
        return None
    return [a.GetComponent(t, c) for t in range(a.GetNumberOfTuples()) for c in range(a.GetNumberOfComponents())]


def check_xml(path):
    """Well-formed XML whose HDF paths are relative and resolve from the .xmf folder."""
    root = ET.parse(path).getroot()
    for item in root.iter("DataItem"):
        if item.get("Format") != "HDF":
            continue
        file_part = item.text.strip().split(":")[0]
        check(not os.path.isabs(file_part), f"{path}: absolute HDF path {item.text}")
        check(os.path.exists(os.path.join(os.path.dirname(path), file_part)), f"{path}: {item.text} does not resolve")


def open_reader(path):
    check_xml(path)
    reader = XDMFReader(FileNames=[path])
    reader.UpdatePipelineInformation()
    return reader


def check_times(what, reader, frames):
    got = list(reader.TimestepValues)
    want = [f["time"] for f in frames]
    check(got == want, f"{what}: time steps {got}, expected the frame times {want}")


def check_particles(spec):
    reader = open_reader(spec["xmf"])
    frames = spec["frames"]
    check_times("particles", reader, frames)
    for f in frames:
        t = f["time"]
        reader.UpdatePipeline(t)
        blocks = leaves(servermanager.Fetch(reader))
        names = [n for n, _ in blocks]
        want_names = ["particles"] + (["contacts"] if f["contacts"] > 0 else [])
        if not check(names == want_names, f"particles t={t}: blocks {names}, expected {want_names}"):
            continue
        p = blocks[0][1]
        check(p.GetNumberOfPoints() == f["points"], f"particles t={t}: {p.GetNumberOfPoints()} points, expected {f['points']}")
        check(p.GetNumberOfCells() == f["points"], f"particles t={t}: {p.GetNumberOfCells()} vertex cells, expected {f['points']}")
        radius = array_values(p.GetPointData(), "radius")
        check(radius == f["radius"], f"particles t={t}: radius {radius}, expected {f['radius']}")
        for array in ("id", "species", "mass", "velocity", "angular_velocity"):
            check(p.GetPointData().GetArray(array) is not None, f"particles t={t}: point array '{array}' missing")
        if f["contacts"] == 0:
            continue
        c = blocks[1][1]
        m = f["contacts"]
        check(c.GetNumberOfPoints() == 2 * m, f"contacts t={t}: {c.GetNumberOfPoints()} points, expected {2 * m}")
        check(c.GetNumberOfCells() == m, f"contacts t={t}: {c.GetNumberOfCells()} cells, expected {m}")
        for k in range(c.GetNumberOfCells()):
            cell = c.GetCell(k)
            check(cell.GetNumberOfPoints() == 2, f"contacts t={t}: cell {k} has {cell.GetNumberOfPoints()} points, expected 2")
            a, b = (c.GetPoint(cell.GetPointId(0)), c.GetPoint(cell.GetPointId(1)))
            length = sum((a[d] - b[d]) ** 2 for d in range(3)) ** 0.5
            check(length < 0.5, f"contacts t={t}: segment {k} is {length} long: drawn across the periodic box?")
        for array in ("force_normal", "force_tangential", "i", "j"):
            data = c.GetCellData().GetArray(array)
            check(data is not None and data.GetNumberOfTuples() == m, f"contacts t={t}: cell array '{array}' missing or wrong length")
    Delete(reader)


def check_fields(spec):
    reader = open_reader(spec["xmf"])
    frames = spec["frames"]
    check_times("fields", reader, frames)
    for f in frames:
        t = f["time"]
        reader.UpdatePipeline(t)
        blocks = leaves(servermanager.Fetch(reader))
        if not check(len(blocks) == 1, f"fields t={t}: {len(blocks)} datasets, expected 1"):
            continue
        g = blocks[0][1]
        check(g.GetNumberOfCells() == f["cells"], f"fields t={t}: {g.GetNumberOfCells()} cells, expected {f['cells']}")
        check(g.GetNumberOfPoints() == f["points"], f"fields t={t}: {g.GetNumberOfPoints()} points, expected {f['points']}")
        bounds = list(g.GetBounds())
        check(bounds == spec["bounds"], f"fields t={t}: bounds {bounds}, expected {spec['bounds']}")
        names = [g.GetCellData().GetArrayName(k) for k in range(g.GetCellData().GetNumberOfArrays())]
        check(names == spec["arrays"], f"fields t={t}: cell arrays {names}, expected {spec['arrays']}")
        ep_g = array_values(g.GetCellData(), "ep_g")
        check(ep_g == f["ep_g"], f"fields t={t}: ep_g {ep_g}, expected {f['ep_g']}")
    Delete(reader)


def main():
    if len(sys.argv) != 2:
        print("usage: pvpython paraview_check.py <expected.json>")
        return 2
    with open(sys.argv[1]) as f:
        expected = json.load(f)
    check_particles(expected["particles"])
    check_fields(expected["fields"])
    for e in errors:
        print("FAIL: " + e)
    if errors:
        return 1
    print("paraview_check: particles.xmf and fields.xmf read as expected")
    return 0


if __name__ == "__main__":
    sys.exit(main())
