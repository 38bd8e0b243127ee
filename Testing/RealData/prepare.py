#!/usr/bin/env python3
"""Writes the real-data test set into a folder (the realdata fixture of the test suite).

The meshes are public test meshes shipped by Debian's libcgal-demo package (CGAL's data/meshes:
scanned models, CAD parts, animal models; see /usr/share/doc/libcgal-dev/copyright). Nothing of
them is committed to this repository: this script reads them from the package's data.tar.gz and
converts them from OFF (which VTK 9.1 has no reader for) to binary PLY with VTK's writer.

It also writes simulation output of its own, as an Exodus II file (VTK's writer): vessel.ex2, a
hexahedral mesh of a thick-walled vessel whose wall bulges in three lobes (the kind of curved
surface a solver's mesh has: quadrilateral faces, coarse around, fine along), with a nodal
temperature; and plate.ex2, a plate with a hole under tension whose nodal stress is Kirsch's
solution (a stress field over a notched part). The geometry is defined here, so it carries no
licence of others.

And it unpacks two files of VTK's own test data committed next to it (vtkdata/, BSD licence, see
vtkdata/README.md): VTK's headsq CT of a head (as headsq.vti) and ParaView's tutorial flow
simulation disk_out_ref.ex2.

usage: prepare.py OUTDIR [--archive data.tar.gz]
"""
import argparse
import math
import os
import sys
import tarfile

import vtk

# name in the test set: (file in data/meshes, kind)
MESHES = {
    "bunny": ("bunny00.off", "scan"),
    "armadillo": ("armadillo.off", "scan"),
    "dragon": ("ChineseDragon-10kv.off", "scan"),
    "lion": ("lion-head.off", "scan"),
    "man": ("man.off", "scan"),
    "femur": ("femur.off", "scan"),
    "fandisk": ("fandisk.off", "cad"),
    "shark": ("mech-holes-shark.off", "cad"),
    "rotor": ("rotor.off", "cad"),
    "pinion": ("pinion.off", "cad"),
    "turbine": ("turbine.off", "cad"),
    "cow": ("cow.off", "model"),
    "elephant": ("elephant.off", "model"),
}

# Written too, for the feature-lines measures (lines.py) only: a scanned head with a face
# (eyes, nose, mouth, ears) and a coarse head.
LINE_MESHES = {
    "mannequin": ("mannequin-devil.off", "scan"),
    "head": ("head.off", "scan"),
}

# 3D images (CGAL's data/images, INRIMAGE-4), written as VTK image data for the volume measures
# (volumes.py): a CT of a skull (64^3 floats, the bone about 2.9) and a segmented liver (uint8
# labels 0/255 on 438 x 353 x 165 samples).
VOLUMES = {
    "skull": "skull_2.9.inr",
    "liver": "liver.inr.gz",
}

ARCHIVES = [
    "/usr/share/doc/libcgal-dev/data.tar.gz",
    "/usr/share/doc/libcgal-demo/data.tar.gz",
]


def parse_off(text, name):
    """The vertices and faces of an OFF file (comments and per-face colours allowed)."""
    tokens = []
    for line in text.splitlines():
        line = line.split("#", 1)[0].strip()
        if line:
            tokens.append(line.split())
    if not tokens or not tokens[0][0].endswith("OFF"):
        raise ValueError(name + ": not an OFF file")
    header = tokens[0][1:] if len(tokens[0]) > 1 else None
    rows = tokens[1:]
    if header is None:
        header, rows = rows[0], rows[1:]
    nv, nf = int(header[0]), int(header[1])
    points = vtk.vtkPoints()
    points.SetDataTypeToFloat()
    points.SetNumberOfPoints(nv)
    for i in range(nv):
        x, y, z = (float(v) for v in rows[i][:3])
        points.SetPoint(i, x, y, z)
    polys = vtk.vtkCellArray()
    for row in rows[nv:nv + nf]:
        n = int(row[0])
        ids = [int(v) for v in row[1:1 + n]]
        if n >= 3 and all(0 <= v < nv for v in ids):
            polys.InsertNextCell(n, ids)
    mesh = vtk.vtkPolyData()
    mesh.SetPoints(points)
    mesh.SetPolys(polys)
    return mesh


def parse_inr(raw, name):
    """An INRIMAGE-4 image (a text header in 256-byte blocks ending in '##}', then the samples)
    as vtkImageData with one float array "density"."""
    import gzip
    import numpy
    from vtk.util import numpy_support

    if raw[:2] == b"\x1f\x8b":
        raw = gzip.decompress(raw)
    end = raw.find(b"##}")
    if not raw.startswith(b"#INRIMAGE-4#{") or end < 0:
        sys.exit("prepare.py: %s is not an INRIMAGE-4 file" % name)
    end = (end + 3 + 1 + 255) // 256 * 256  # the header fills whole 256-byte blocks
    fields = dict(line.split("=", 1) for line in raw[:end].decode("ascii", "replace").splitlines()
                  if "=" in line)
    dims = [int(fields[k]) for k in ("XDIM", "YDIM", "ZDIM")]
    kind = (fields["TYPE"], int(fields["PIXSIZE"].split()[0]))
    dtype = {("float", 32): "f4", ("float", 64): "f8", ("unsigned fixed", 8): "u1",
             ("unsigned fixed", 16): "u2", ("signed fixed", 16): "i2"}[kind]
    order = ">" if fields.get("CPU", "decm") in ("sun", "sgi") else "<"
    count = dims[0] * dims[1] * dims[2]
    samples = numpy.frombuffer(raw[end:], dtype=order + dtype, count=count).astype(numpy.float32)
    image = vtk.vtkImageData()
    image.SetDimensions(*dims)
    image.SetSpacing(*(float(fields.get(k, 1)) for k in ("VX", "VY", "VZ")))
    array = numpy_support.numpy_to_vtk(samples, deep=1)
    array.SetName("density")
    image.GetPointData().SetScalars(array)
    return image


def write_vessel(path):
    """A hollow vessel of hexahedra (radius 0.5 to 2, height 4) with three lobes, as Exodus II."""
    nr, nt, nz = 4, 48, 32
    points = vtk.vtkPoints()
    temperature = vtk.vtkDoubleArray()
    temperature.SetName("Temp")
    for k in range(nz + 1):
        z = 4.0 * k / nz
        for j in range(nt):
            theta = 2.0 * math.pi * j / nt
            lobe = 1.0 + 0.18 * math.sin(3.0 * theta) * math.sin(math.pi * z / 4.0)
            for i in range(nr + 1):
                r = (0.5 + 1.5 * i / nr) * lobe
                points.InsertNextPoint(r * math.cos(theta), r * math.sin(theta), z)
                temperature.InsertNextValue(300.0 + 50.0 * z + 20.0 * r)
    write_ring_grid(path, points, [temperature], nr, nt, nz)


def write_plate(path):
    """A plate with a central hole under tension along x, of hexahedra, as Exodus II: the
    nodal stress is Kirsch's solution (the elastic stress around a circular hole in a plate
    pulled by a remote stress of 1), the stress field of a notched plate that a solver would
    give: sigma_xx from -1 beside the hole on the pulling axis to 3 across it, von Mises."""
    a, half, thick = 1.0, 4.0, 0.4
    nr, nt, nz = 24, 96, 2
    points = vtk.vtkPoints()
    sxx = vtk.vtkDoubleArray()
    sxx.SetName("StressXX")
    mises = vtk.vtkDoubleArray()
    mises.SetName("VonMises")
    for k in range(nz + 1):
        z = thick * k / nz
        for j in range(nt):
            theta = 2.0 * math.pi * j / nt
            c, s = math.cos(theta), math.sin(theta)
            edge = half / max(abs(c), abs(s))  # the ray's exit through the square's side
            for i in range(nr + 1):
                t = (i / nr) ** 1.6  # graded towards the hole, as a solver's mesh is
                r = a + (edge - a) * t
                points.InsertNextPoint(r * c, r * s, z)
                q2, q4 = (a / r) ** 2, (a / r) ** 4
                c2, s2 = math.cos(2.0 * theta), math.sin(2.0 * theta)
                srr = 0.5 * (1.0 - q2) + 0.5 * (1.0 - 4.0 * q2 + 3.0 * q4) * c2
                stt = 0.5 * (1.0 + q2) - 0.5 * (1.0 + 3.0 * q4) * c2
                srt = -0.5 * (1.0 + 2.0 * q2 - 3.0 * q4) * s2
                xx = srr * c * c + stt * s * s - 2.0 * srt * s * c
                yy = srr * s * s + stt * c * c + 2.0 * srt * s * c
                xy = (srr - stt) * s * c + srt * (c * c - s * s)
                sxx.InsertNextValue(xx)
                mises.InsertNextValue(math.sqrt(xx * xx - xx * yy + yy * yy + 3.0 * xy * xy))
    write_ring_grid(path, points, [sxx, mises], nr, nt, nz)


def write_ring_grid(path, points, arrays, nr, nt, nz):
    """Writes as Exodus II the hexahedra of a grid of points laid out (k, j, i): nz + 1 layers,
    nt around (closed: j wraps), nr + 1 along, with the point arrays, one element block."""
    grid = vtk.vtkUnstructuredGrid()
    grid.SetPoints(points)
    for array in arrays:
        grid.GetPointData().AddArray(array)

    def pid(i, j, k):
        return (k * nt + j % nt) * (nr + 1) + i
    for k in range(nz):
        for j in range(nt):
            for i in range(nr):
                ids = [pid(i, j, k), pid(i + 1, j, k), pid(i + 1, j + 1, k), pid(i, j + 1, k),
                       pid(i, j, k + 1), pid(i + 1, j, k + 1), pid(i + 1, j + 1, k + 1),
                       pid(i, j + 1, k + 1)]
                grid.InsertNextCell(vtk.VTK_HEXAHEDRON, 8, ids)
    blocks = vtk.vtkIntArray()
    blocks.SetName("ElementBlockIds")
    blocks.SetNumberOfTuples(grid.GetNumberOfCells())
    blocks.Fill(1)
    grid.GetCellData().AddArray(blocks)
    writer = vtk.vtkExodusIIWriter()
    writer.WriteAllTimeStepsOff()
    write(writer, grid, path)
    print(path, grid.GetNumberOfPoints(), "points", grid.GetNumberOfCells(), "hexahedra")


def unpack_vtk_data(outdir):
    """headsq.vti (VTK's headsq: 64 x 64 x 93 16-bit samples, masked with 0x7fff as VTK's
    examples read them, spacing 3.2, 3.2, 1.5) and disk_out_ref.ex2, from vtkdata/."""
    import gzip
    import lzma
    import numpy
    from vtk.util import numpy_support

    here = os.path.join(os.path.dirname(os.path.abspath(__file__)), "vtkdata")
    out = os.path.join(outdir, "headsq.vti")
    if not os.path.exists(out):
        with open(os.path.join(here, "headsq.raw.xz"), "rb") as f:
            raw = lzma.decompress(f.read())
        if len(raw) != 64 * 64 * 93 * 2:
            sys.exit("prepare.py: vtkdata/headsq.raw.xz holds %d bytes, not 64 x 64 x 93 x 2"
                     % len(raw))
        samples = numpy.frombuffer(raw, dtype="<i2") & 0x7FFF
        image = vtk.vtkImageData()
        image.SetDimensions(64, 64, 93)
        image.SetSpacing(3.2, 3.2, 1.5)
        array = numpy_support.numpy_to_vtk(samples.astype(numpy.int16), deep=1)
        array.SetName("density")
        image.GetPointData().SetScalars(array)
        writer = vtk.vtkXMLImageDataWriter()
        writer.SetCompressorTypeToZLib()
        write(writer, image, out)
        print(out, image.GetDimensions(), "samples")
    out = os.path.join(outdir, "disk_out_ref.ex2")
    if not os.path.exists(out):
        with gzip.open(os.path.join(here, "disk_out_ref.ex2.gz"), "rb") as f:
            raw = f.read()
        with open(out + ".part", "wb") as f:
            f.write(raw)
        os.replace(out + ".part", out)
        print(out, len(raw), "bytes")


def write(writer, data, path):
    """Writes data with writer to a temporary name next to path, then renames it: an interrupted
    run leaves no partial file that a later run would take as done."""
    stem, ext = os.path.splitext(path)
    writer.SetFileName(stem + ".part" + ext)
    writer.SetInputData(data)
    if not writer.Write():
        sys.exit("prepare.py: cannot write " + path)
    os.replace(stem + ".part" + ext, path)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("outdir")
    parser.add_argument("--archive", help="CGAL's data.tar.gz (default: the libcgal-demo package's)")
    args = parser.parse_args()
    archive = args.archive or next((a for a in ARCHIVES if os.path.exists(a)), None)
    if not archive:
        sys.exit("prepare.py: CGAL's data.tar.gz not found (install Debian's libcgal-demo; "
                 "scripts/test.sh does)")
    os.makedirs(args.outdir, exist_ok=True)
    with tarfile.open(archive) as tar:
        for name, (member, _kind) in {**MESHES, **LINE_MESHES}.items():
            out = os.path.join(args.outdir, name + ".ply")
            if os.path.exists(out):
                continue
            text = tar.extractfile("data/meshes/" + member).read().decode("latin-1")
            mesh = parse_off(text, member)
            writer = vtk.vtkPLYWriter()
            writer.SetFileTypeToBinary()
            write(writer, mesh, out)
            print(out, mesh.GetNumberOfPoints(), "points", mesh.GetNumberOfCells(), "faces")
        for name, member in VOLUMES.items():
            out = os.path.join(args.outdir, name + ".vti")
            if not os.path.exists(out):
                image = parse_inr(tar.extractfile("data/images/" + member).read(), member)
                writer = vtk.vtkXMLImageDataWriter()
                writer.SetCompressorTypeToZLib()
                write(writer, image, out)
                print(out, image.GetDimensions(), "samples")
    vessel = os.path.join(args.outdir, "vessel.ex2")
    if not os.path.exists(vessel):
        write_vessel(vessel)
    plate = os.path.join(args.outdir, "plate.ex2")
    if not os.path.exists(plate):
        write_plate(plate)
    unpack_vtk_data(args.outdir)


if __name__ == "__main__":
    main()
