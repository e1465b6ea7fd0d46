#!/usr/bin/env python3
"""The two flow engines side by side on the paper's channel (docs/validation.md "The two engines
on the paper's channel"): examples/bridge_piers.yaml's flow without its logs, one hour, run by
`flotsam run` with each engine and step, and compared on the mean inflow discharge over the last
20 minutes and the mean water surface over the same 20 minutes at four gauges upstream of each
bridge.

    python3 bench/compare_engines.py BUILD_DIR OUT_DIR [RUN ...]

RUN names one of the runs below (default: all; `fem_0.1` alone takes about 35 minutes on this
machine, the others a few minutes each). Runs whose results are already in OUT_DIR are not run
again.
"""
import csv
import os
import subprocess
import sys

# name: (engine, coupling step [s], fv cells, mesh_size [m], pier_mesh_size [m])
RUNS = {
    "fem_1": ("fem", 1.0, None, 14.5, 4.0),
    "fem_0.1": ("fem", 0.1, None, 14.5, 4.0),
    "fv_elements": ("fv", 1.0, "elements", 14.5, 4.0),
    "fv_split": ("fv", 1.0, "split", 14.5, 4.0),
    "fv_fine": ("fv", 1.0, "elements", 7.25, 2.0),
}
GAUGES = [(f"b{b}_{k}", x, y) for b, x in ((1, 550.0), (2, 850.0))
          for k, y in enumerate((10.0, 42.5, 85.0, 127.5))]
T_END, WINDOW = 3600.0, 1200.0  # [s]


def case_text(name, engine, step, cells, size, pier_size):
    fv = f"  fv: {{cells: {cells}}}\n" if engine == "fv" else ""
    probes = "".join(f"    - {{name: {g}, x: {x}, y: {y}}}\n" for g, x, y in GAUGES)
    return f"""name: {name}
mesh:
  channel:
    length: 1500
    width: 170
    mesh_size: {size}
    pier_mesh_size: {pier_size}
    piers:
      - {{x: 600, y: 42.5, radius: 30}}
      - {{x: 600, y: 127.5, radius: 30}}
      - {{x: 900, y: 42.5, radius: 30}}
      - {{x: 900, y: 127.5, radius: 30}}
flow:
  engine: {engine}
{fv}  reynolds: {{number: 1000, reference_velocity: 0.5, reference_length: 60}}
  friction: {{law: manning, coefficient: 0.03}}
  initial: {{eta_start: 10.0, eta_end: 9.80}}
  boundaries:
    inflow: {{type: elevation, value: 10.0}}
    outflow: {{type: elevation, value: 9.80}}
    bank_right: {{type: wall}}
    bank_left: {{type: wall}}
    pier_1: {{type: wall}}
    pier_2: {{type: wall}}
    pier_3: {{type: wall}}
    pier_4: {{type: wall}}
time: {{end: {T_END}, step: {step}, mode: one-way}}
output:
  interval: 600
  probes:
{probes}"""


def rows(path):
    with open(path) as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def summarise(out_dir, name):
    balance = rows(os.path.join(out_dir, name, f"{name}_balance.csv"))
    # the output rows nearest the window's ends (a step of 0.1 s puts them at 2400.1 s)
    start = min(balance, key=lambda r: abs(r["t [s]"] - (T_END - WINDOW)))
    end = min(balance, key=lambda r: abs(r["t [s]"] - T_END))
    q_in = -(end["outflow inflow [m^3]"] - start["outflow inflow [m^3]"]) / (
        end["t [s]"] - start["t [s]"])
    probes = [r for r in rows(os.path.join(out_dir, name, f"{name}_probes.csv"))
              if r["t [s]"] > T_END - WINDOW]
    eta = {g: sum(r[f"{g}_eta [m]"] for r in probes) / len(probes) for g, _, _ in GAUGES}
    return q_in, eta


def finished(out_dir, name):
    path = os.path.join(out_dir, name, f"{name}_probes.csv")
    return os.path.exists(path) and rows(path)[-1]["t [s]"] >= T_END


def main():
    build, out_dir = sys.argv[1], sys.argv[2]
    names = sys.argv[3:] or list(RUNS)
    os.makedirs(out_dir, exist_ok=True)
    for name in names:
        if not finished(out_dir, name):
            case = os.path.join(out_dir, f"{name}.yaml")
            with open(case, "w") as f:
                f.write(case_text(name, *RUNS[name]))
            subprocess.run([os.path.join(build, "flotsam"), "run", case, "-o",
                            os.path.join(out_dir, name), "--overwrite", "-q"], check=True)
    done = [n for n in RUNS if finished(out_dir, n)]
    results = {n: summarise(out_dir, n) for n in done}
    print("run            Q_in [m^3/s]  " + "  ".join(g for g, _, _ in GAUGES))
    for n in done:
        q, eta = results[n]
        print(f"{n:14s} {q:12.1f}  " + "  ".join(f"{eta[g]:6.3f}" for g, _, _ in GAUGES))


if __name__ == "__main__":
    main()
