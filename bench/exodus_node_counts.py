#!/usr/bin/python3
"""Which node counts per element VTK's Exodus reader reads right (io/exodus_rules.cpp's table).

Writes the twisted mixed mesh as Exodus (`cellproj generate mixed`), then, for each block and each
candidate count, pads every element's connectivity with node 1 up to that count (ncdump / ncgen)
and reads the file with VTK's vtkExodusIIReader. Right: the block's second cell has the corners of
the unpadded file's second cell, compared by coordinates. Needs Debian's python3 with
VTK and netcdf-bin.
usage: bench/exodus_node_counts.py [CELLPROJ]   (prints one line per type and count)
"""
import os, re, subprocess, sys, tempfile
import vtk

exe = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "build", "bin", "cellproj")
work = tempfile.mkdtemp()
base = os.path.join(work, "mixed.exo")
subprocess.run([exe, "generate", "mixed", "-n", "2", "-o", base], check=True, stdout=subprocess.DEVNULL)
cdl = subprocess.run(["ncdump", base], check=True, capture_output=True, text=True).stdout
candidates = {"TET": [4, 5, 8, 10, 11, 14, 15], "HEX": [8, 9, 16, 20, 27], "WED": [6, 12, 15, 16, 18, 21, 24],
              "PYR": [5, 13, 14, 18, 19]}


def second_cell(path, block):
    r = vtk.vtkExodusIIReader()
    r.SetFileName(path)
    r.UpdateInformation()
    for i in range(r.GetNumberOfObjects(vtk.vtkExodusIIReader.ELEM_BLOCK)):
        r.SetObjectStatus(vtk.vtkExodusIIReader.ELEM_BLOCK, i, 1)
    r.Update()
    b = r.GetOutput().GetBlock(0).GetBlock(block - 1)
    c = b.GetCell(1)
    return c.GetClassName(), [tuple(round(x, 9) for x in b.GetPoint(c.GetPointId(k))) for k in range(c.GetNumberOfPoints())]


for block in range(1, 5):
    kind = re.search(rf'connect{block}:elem_type = "(\w+)"', cdl).group(1)
    linear = int(re.search(rf"num_nod_per_el{block} = (\d+) ;", cdl).group(1))
    conn = re.search(rf"connect{block} =([^;]*);", cdl)
    ids = [v.strip() for v in conn.group(1).replace("\n", " ").split(",")]
    _, want = second_cell(base, block)
    for n in candidates[kind[:3].upper()]:
        padded = [x for e in range(len(ids) // linear) for x in ids[linear * e:linear * (e + 1)] + ["1"] * (n - linear)]
        text = cdl.replace(f"num_nod_per_el{block} = {linear} ;", f"num_nod_per_el{block} = {n} ;")
        text = text.replace(conn.group(0), f"connect{block} = " + ", ".join(padded) + " ;")
        path = os.path.join(work, f"{kind}{n}.exo")
        with open(path + ".cdl", "w") as f:
            f.write(text)
        subprocess.run(["ncgen", "-o", path, path + ".cdl"], check=True)
        cls, got = second_cell(path, block)
        right = got[:linear] == want[:linear]
        print(f"{kind:8} {n:3}  {cls:30} {'right' if right else 'WRONG: the second element is read on other nodes'}")
