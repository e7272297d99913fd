#!/usr/bin/env python3
"""LAMMPS data files for demsweep's 3D benchmark block (src/bench/block3d.rs), written here:

  block_rot3d.data     atom_style bpm/sphere (in.bpm_rot3d: bond_style bpm/rotational)
  block_spring3d.data  atom_style bond       (in.bpm_spring3d: bond_style bpm/spring)
  params3d.in          the springs, time step, counts, as LAMMPS variables

The block is packing3d::fcc of a cube of side 30 R, R = 5 mm, rebuilt with the same float
operations (so the same bits): a simple cubic grid of pitch h = sqrt(2) R from the low corner
shifted by R, n = floor((30R - 2R)/h + 1e-9) + 1 = 20 planes a side, the sites whose indices sum
to an even number, in k, j, i order -> 4000 spheres; bonds join the pairs closer than
2R + 1e-9 R (every touching pair) -> 21 660 bonds. The initial velocities are block3d's seeded
field (the same 64-bit LCG, the same order: 0.2 * (u - 0.5) per component), no spin.
Masses: rho = 2400 kg/m^3 on solid spheres (LAMMPS: from the density column; demsweep:
rho 4/3 pi r^3), inertia 0.4 m r^2 in both.

Springs (block3d's class at r_bar = R): k_n = 60 GPa * R = 3e8 N/m, k_s = 0.25 k_n; the MTL's
rolling k_r = 0.25 * 60 GPa * R^3 and twisting k_t = 0.125 * 60 GPa * R^3 act on HALF the
relative rotation (rolling::increment, twisting::moment), so the torque per radian of relative
rotation is k_r / 2 and k_t / 2: those are bpm/rotational's Kb and Kt (torque = K * angle).

usage: make_data3d.py DT_S   (demsweep's time step for this block, from `demsweep bench
--workload block3d` with bench_dt.patch applied; see ../bench_peers3d.sh)
"""
import math
import sys

R = 0.005
SIDE = 30.0 * R
KAPPA = 60e9
RHO = 2400.0
KN = KAPPA * R
KS = 0.25 * KAPPA * R
KR = 0.25 * KAPPA * R ** 3
KT = 0.125 * KAPPA * R ** 3


def planes(lo, hi, pitch):
    return 0 if hi < lo else math.floor((hi - lo) / pitch + 1e-9) + 1


def fcc():
    r, h = R, math.sqrt(2.0) * R
    lo, hi = 0.0, SIDE
    n = planes(lo + r, hi - r, h)
    centres = []
    for k in range(n):
        for j in range(n):
            for i in range(n):
                if (i + j + k) % 2 == 0:
                    centres.append((lo + r + h * i, lo + r + h * j, lo + r + h * k))
    return centres


def bonds_within(centres, gap):
    # A cell grid of side >= the reach; pairs (i < j) closer than 2R + gap, sorted as demsweep's.
    reach = 2.0 * R + gap
    cells = {}
    for e, c in enumerate(centres):
        cells.setdefault(tuple(int(v // reach) for v in c), []).append(e)
    out = []
    for e, c in enumerate(centres):
        key = tuple(int(v // reach) for v in c)
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for dz in (-1, 0, 1):
                    for f in cells.get((key[0] + dx, key[1] + dy, key[2] + dz), ()):
                        if f > e:
                            d2 = sum((a - b) ** 2 for a, b in zip(c, centres[f]))
                            if d2 < reach * reach:
                                out.append((e, f))
    out.sort()
    return out


def velocities(n):
    s = 0x3D_B10C
    mask = (1 << 64) - 1

    def rnd():
        nonlocal s
        s = (s * 6364136223846793005 + 1442695040888963407) & mask
        return (s >> 11) / float(1 << 53) - 0.5

    return [(0.2 * rnd(), 0.2 * rnd(), 0.2 * rnd()) for _ in range(n)]


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    dt = float(sys.argv[1])
    centres = fcc()
    bonds = bonds_within(centres, 1e-9 * R)
    vel = velocities(len(centres))
    mass = RHO * 4.0 / 3.0 * math.pi * R ** 3
    assert len(centres) == 4000 and len(bonds) == 21660, (len(centres), len(bonds))
    pad = 0.1  # fixed boundaries well clear of the block (it only vibrates)
    box = "%r %r xlo xhi\n%r %r ylo yhi\n%r %r zlo zhi\n\n" % ((-pad, SIDE + pad) * 3)

    def head(f, style):
        f.write("demsweep block3d: fcc block of side 30 R, R = 5 mm, every touching pair bonded (%s)\n\n" % style)
        f.write("%d atoms\n1 atom types\n%d bonds\n1 bond types\n\n" % (len(centres), len(bonds)))
        f.write(box)

    def tail(f, spin):
        f.write("\nVelocities\n\n")
        for e, v in enumerate(vel):
            f.write("%d %.17g %.17g %.17g%s\n" % (e + 1, v[0], v[1], v[2], " 0 0 0" if spin else ""))
        f.write("\nBonds\n\n")
        for b, (i, j) in enumerate(bonds):
            f.write("%d 1 %d %d\n" % (b + 1, i + 1, j + 1))

    # bpm/sphere: atom-ID molecule-ID atom-type diameter density x y z
    with open("block_rot3d.data", "w") as f:
        head(f, "bpm/sphere")
        f.write("Atoms # bpm/sphere\n\n")
        for e, c in enumerate(centres):
            f.write("%d 1 1 %.17g %.17g %.17g %.17g %.17g\n" % (e + 1, 2 * R, RHO, c[0], c[1], c[2]))
        tail(f, True)
    # bond: atom-ID molecule-ID atom-type x y z
    with open("block_spring3d.data", "w") as f:
        head(f, "bond")
        f.write("Masses\n\n1 %.17g\n\n" % mass)
        f.write("Atoms # bond\n\n")
        for e, c in enumerate(centres):
            f.write("%d 1 1 %.17g %.17g %.17g\n" % (e + 1, c[0], c[1], c[2]))
        tail(f, False)
    with open("params3d.in", "w") as f:
        f.write("# generated by make_data3d.py: demsweep's block3d\n")
        for k, v in (("R", R), ("DT", dt), ("MASS", mass), ("KN", KN), ("KS", KS),
                     ("KB", KR / 2.0), ("KT", KT / 2.0)):
            f.write("variable %s equal %.17g\n" % (k, v))
        f.write("variable NATOMS equal %d\nvariable NBONDS equal %d\n" % (len(centres), len(bonds)))
    print("%d atoms, %d bonds, mass %.6e kg, dt %.6e s, kn %.4g ks %.4g Kb %.4g Kt %.4g"
          % (len(centres), len(bonds), mass, dt, KN, KS, KR / 2, KT / 2))


main()
