#!/usr/bin/python3
"""How the twist of Suchde & Kuhnert's half pipe (§4.2.2, eq 35) deforms each placement.

The paper's figure of the half pipe is lost, so its placement relative to the velocity
(−yz, 0, xz) is a reconstruction. This moves a fine parameter grid of every half of the
tube (radius 0.25 about a 180° arc of radius 0.75 about the origin) by that velocity alone
(RK4, Δt = 0.005, to t = 2) and prints its area and its largest curvature |∇n| at
t = 0.5, 1, 1.5, 2. A placement whose curvature grows beyond about 1/h cannot be followed by
a cloud of smoothing length h (h = 0.05 in the paper: curvature 20). The case file
cases/surface_half_pipe.toml uses the arc in the x–z plane and its inner half.
"""

import numpy as np

PIPE, ARC = 0.25, 0.75
AXES = "xyz"
HALVES = {"upper": (0.0, np.pi), "lower": (np.pi, 2 * np.pi),
          "outer": (-0.5 * np.pi, 0.5 * np.pi), "inner": (0.5 * np.pi, 1.5 * np.pi)}


def twist(p):
    x, y, z = p[..., 0], p[..., 1], p[..., 2]
    return np.stack([-y * z, 0.0 * x, x * z], axis=-1)


def largest_curvature(p):
    du, dv = np.gradient(p, axis=0), np.gradient(p, axis=1)
    n = np.cross(du, dv)
    n /= np.linalg.norm(n, axis=-1)[..., None]
    along_u = np.linalg.norm(np.gradient(n, axis=0), axis=-1) / np.linalg.norm(du, axis=-1)
    along_v = np.linalg.norm(np.gradient(n, axis=1), axis=-1) / np.linalg.norm(dv, axis=-1)
    return np.maximum(along_u, along_v).max()


def area(p):
    return np.linalg.norm(np.cross(p[1:, :-1] - p[:-1, :-1], p[:-1, 1:] - p[:-1, :-1]),
                          axis=-1).sum()


def main():
    unit = np.eye(3)
    theta = np.linspace(-0.5 * np.pi, 0.5 * np.pi, 301)
    print("arc plane (e_r = cos θ a + sin θ b), half (offset direction in (e_r, c)): "
          "area t = 0 -> 2, largest curvature at t = 0.5, 1, 1.5, 2")
    for a, b in [(0, 2), (2, 0), (1, 2), (2, 1), (0, 1), (1, 0)]:
        c = 3 - a - b
        for name, (start, end) in HALVES.items():
            t, phi = np.meshgrid(theta, np.linspace(start, end, 151), indexing="ij")
            radial = np.cos(t)[..., None] * unit[a] + np.sin(t)[..., None] * unit[b]
            p = (ARC + PIPE * np.cos(phi))[..., None] * radial + (PIPE * np.sin(phi))[..., None] * unit[c]
            initial, dt, curvatures = area(p), 0.005, []
            for step in range(1, 401):
                k1 = twist(p)
                k2 = twist(p + 0.5 * dt * k1)
                k3 = twist(p + 0.5 * dt * k2)
                k4 = twist(p + dt * k3)
                p = p + dt / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4)
                if step % 100 == 0:
                    curvatures.append(largest_curvature(p))
            print(f"  a = {AXES[a]}, b = {AXES[b]}, c = {AXES[c]}, {name:5s}: area {initial:.2f} -> "
                  f"{area(p):.2f}, curvature " + " ".join(f"{k:.0f}" for k in curvatures))


if __name__ == "__main__":
    main()
