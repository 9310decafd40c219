"""The grain-chaff combine's fields at one instant, as ParaView reads them (issue 29).

    pvpython scripts/combine_fields.py <product folder>/fields.xmf [--time 5] [--table out.dat]

Opens the mfm stage's fields.xmf with ParaView's XDMFReader (the reader a user opens it with),
takes the frame at --time (the reference's Figs. 4.7-4.11 show 5 s) and prints, row by row of
cells from the bottom, the x-z means of ep_s_grain and ep_s_chaff and the vertical velocity of the
gas, the grain and the chaff (solids-weighted), then the same for the central x-y plane column by
column along x (Figs. 4.7 and 4.9's plane). --table writes the central plane cell by cell
(x, y, ep_s_grain, ep_s_chaff, u_g, v_g, u_chaff, v_chaff) for gnuplot. The row table's last
columns are the gas's vertical velocity where the chaff is (chaff-weighted) and the chaff's slip
against it, beside a lone chaff sphere's settling speed in still air (0.971 m/s under Eq. 3.16):
the gas a falling plume drags down with it shows there (issue 56).
"""
import argparse
import sys

from paraview import servermanager
from paraview.simple import XDMFReader


def leaf(data):
    while data.IsA("vtkMultiBlockDataSet"):
        data = data.GetBlock(0)
    return data


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("xmf")
    ap.add_argument("--time", type=float, default=5.0)
    ap.add_argument("--table")
    args = ap.parse_args()
    reader = XDMFReader(FileNames=[args.xmf])
    reader.UpdatePipelineInformation()
    times = list(reader.TimestepValues)
    t = min(times, key=lambda x: abs(x - args.time))
    reader.UpdatePipeline(t)
    g = leaf(servermanager.Fetch(reader))
    cd = g.GetCellData()
    arrays = {name: cd.GetArray(name) for name in ("ep_s_grain", "ep_s_chaff", "u_g", "u_s_grain", "u_s_chaff")}
    missing = [n for n, a in arrays.items() if a is None]
    if missing:
        print(f"{args.xmf}: no cell arrays {missing}")
        return 1
    cells = []
    for k in range(g.GetNumberOfCells()):
        b = g.GetCell(k).GetBounds()
        cells.append(((b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2, k))
    xs = sorted({round(c[0], 9) for c in cells})
    ys = sorted({round(c[1], 9) for c in cells})
    zs = sorted({round(c[2], 9) for c in cells})
    grain, chaff = arrays["ep_s_grain"], arrays["ep_s_chaff"]
    print(f"{args.xmf} at t = {t:g} s: {len(xs)} x {len(ys)} x {len(zs)} cells")
    print("row  y[cm]  ep_s_grain  ep_s_chaff   u_g[m/s] v_g[m/s]  u_chaff  v_grain  v_chaff  v_g@chaff  slip  (x-z means; "
          "solids' velocities and v_g@chaff solids-weighted, slip = v_chaff - v_g@chaff)")
    for j, y in enumerate(ys):
        row = [c[3] for c in cells if round(c[1], 9) == y]
        eg = sum(grain.GetValue(k) for k in row) / len(row)
        ec = sum(chaff.GetValue(k) for k in row) / len(row)
        ug = sum(arrays["u_g"].GetComponent(k, 0) for k in row) / len(row)
        vg = sum(arrays["u_g"].GetComponent(k, 1) for k in row) / len(row)
        wg = sum(grain.GetValue(k) for k in row)
        wc = sum(chaff.GetValue(k) for k in row)
        vgr = sum(grain.GetValue(k) * arrays["u_s_grain"].GetComponent(k, 1) for k in row) / wg if wg > 0 else 0.0
        vch = sum(chaff.GetValue(k) * arrays["u_s_chaff"].GetComponent(k, 1) for k in row) / wc if wc > 0 else 0.0
        uch = sum(chaff.GetValue(k) * arrays["u_s_chaff"].GetComponent(k, 0) for k in row) / wc if wc > 0 else 0.0
        vgc = sum(chaff.GetValue(k) * arrays["u_g"].GetComponent(k, 1) for k in row) / wc if wc > 0 else 0.0
        print(f"{j:3d} {100 * y:6.1f}  {eg:10.3e}  {ec:10.3e}  {ug:8.3f} {vg:8.3f} {uch:8.3f} {vgr:8.3f} {vch:8.3f}"
              f" {vgc:9.3f} {vch - vgc:6.3f}")
    zc = zs[len(zs) // 2]
    plane = [c for c in cells if round(c[2], 9) == zc]
    print(f"central x-y plane (z = {100 * zc:.0f} cm), column means over y, along x:")
    print(" x[cm]  ep_s_grain  ep_s_chaff  u_chaff[m/s]")
    for x in xs:
        col = [c[3] for c in plane if round(c[0], 9) == x]
        eg = sum(grain.GetValue(k) for k in col) / len(col)
        ec = sum(chaff.GetValue(k) for k in col) / len(col)
        wc = sum(chaff.GetValue(k) for k in col)
        uch = sum(chaff.GetValue(k) * arrays["u_s_chaff"].GetComponent(k, 0) for k in col) / wc if wc > 0 else 0.0
        print(f"{100 * x:6.1f}  {eg:10.3e}  {ec:10.3e}  {uch:9.3f}")
    if args.table:
        with open(args.table, "w") as f:
            f.write("# x y ep_s_grain ep_s_chaff u_g v_g u_chaff v_chaff\n")
            for x in xs:
                for c in sorted((c for c in plane if round(c[0], 9) == x), key=lambda c: c[1]):
                    k = c[3]
                    f.write(f"{c[0]} {c[1]} {grain.GetValue(k)} {chaff.GetValue(k)} "
                            f"{arrays['u_g'].GetComponent(k, 0)} {arrays['u_g'].GetComponent(k, 1)} "
                            f"{arrays['u_s_chaff'].GetComponent(k, 0)} {arrays['u_s_chaff'].GetComponent(k, 1)}\n")
                f.write("\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
