"""cosserat.plot and cosserat.animate: pictures of a solve's output (matplotlib; ffmpeg for MP4,
Pillow for GIF, both from Debian)."""
import numpy as np


def _pyplot():
    import matplotlib
    if matplotlib.get_backend().lower().startswith("qt") and not _has_display():
        matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def _has_display():
    import os
    return bool(os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY"))


def _view(points):
    """The two world axes the rod spans most (x–z for a rod hanging in the x–z plane)."""
    spread = np.ptp(points.reshape(-1, 3), axis=0)
    a, b = sorted(np.argsort(spread)[-2:])
    return a, b


def plot(out, ax=None):
    """Draws the rod of a solve's output (cosserat.solve) in the plane it spans most, and for
    dynamics its tip's path. Returns the matplotlib axes."""
    plt = _pyplot()
    result = out["result"] if "result" in out else out
    nodes = np.asarray(result["nodes"]["position"], dtype=float)
    traj = result.get("trajectory")
    tip = np.asarray(traj["tip_position"], dtype=float) if traj else None
    a, b = _view(np.vstack([nodes] + ([tip] if tip is not None else [])))
    if ax is None:
        _, ax = plt.subplots(figsize=(6, 5))
    ax.plot(nodes[:, a], nodes[:, b], "-", lw=2, label="rod")
    ax.plot(nodes[0, a], nodes[0, b], "ks", ms=6, label="base")
    if tip is not None:
        ax.plot(tip[:, a], tip[:, b], "-", lw=0.8, alpha=0.7, label="tip path")
    ax.set_xlabel("xyz"[a] + " [m]")
    ax.set_ylabel("xyz"[b] + " [m]")
    ax.set_aspect("equal", adjustable="datalim")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_title(f"status: {result.get('status')}")
    return ax


def animate(out, path, fps=25, every=1):
    """Writes an animation of a dynamics run to `path`: MP4 through ffmpeg, GIF through Pillow
    (by the file's extension). `out` is cosserat.solve(problem, nodes=True) of a dynamics problem
    (its "frames"); `every` keeps every n-th frame. Returns the number of frames written."""
    plt = _pyplot()
    from matplotlib import animation
    frames = out.get("frames")
    if frames is None:
        raise ValueError("animate: needs cosserat.solve(problem, nodes=True) of a dynamics problem "
                         "(its output has no \"frames\")")
    t = frames["t"][::every]
    p = frames["position"][::every]
    a, b = _view(p)
    fig, ax = plt.subplots(figsize=(6, 5))
    lo, hi = p.reshape(-1, 3).min(axis=0), p.reshape(-1, 3).max(axis=0)
    pad = 0.05 * max(hi[a] - lo[a], hi[b] - lo[b], 1e-9)
    ax.set_xlim(lo[a] - pad, hi[a] + pad)
    ax.set_ylim(lo[b] - pad, hi[b] + pad)
    ax.set_aspect("equal")
    ax.set_xlabel("xyz"[a] + " [m]")
    ax.set_ylabel("xyz"[b] + " [m]")
    ax.grid(True, alpha=0.3)
    (line,) = ax.plot([], [], "-", lw=2)
    label = ax.text(0.02, 0.95, "", transform=ax.transAxes)

    def draw(k):
        line.set_data(p[k][:, a], p[k][:, b])
        label.set_text(f"t = {t[k]:.3f} s")
        return line, label

    anim = animation.FuncAnimation(fig, draw, frames=len(t), blit=True)
    if str(path).lower().endswith(".gif"):
        writer = animation.PillowWriter(fps=fps)
    else:
        if not animation.FFMpegWriter.isAvailable():
            plt.close(fig)
            raise RuntimeError("animate: MP4 needs ffmpeg (apt install ffmpeg); a .gif path "
                               "uses Pillow instead")
        writer = animation.FFMpegWriter(fps=fps)
    anim.save(str(path), writer=writer)
    plt.close(fig)
    return len(t)
