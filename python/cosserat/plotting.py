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


_VIDEO = (".mp4", ".mov", ".mkv", ".webm", ".avi")  # written by ffmpeg


def _view(points):
    """The two world axes the rod spans most (x–z for a rod hanging in the x–z plane)."""
    spread = np.ptp(points.reshape(-1, 3), axis=0)
    a, b = sorted(np.argsort(spread)[-2:])
    return a, b


def _rods(result):
    """The node positions (N_i x 3, m) of every rod of a result: one for a rod, one per rod of
    an assembly."""
    if "assembly" in result:
        return [np.asarray(r["nodes"]["position"], dtype=float)
                for r in result["assembly"]["rods"]]
    if "nodes" not in result:
        raise ValueError(f"plot: the result has no node positions (status {result.get('status')})")
    return [np.asarray(result["nodes"]["position"], dtype=float)]


def plot(out, ax=None):
    """Draws the rod of a solve's output (cosserat.solve), or every rod and body of an assembly,
    in the plane they span most, and for dynamics of a rod its tip's path. Returns the
    matplotlib axes."""
    plt = _pyplot()
    result = out["result"] if "result" in out else out
    rods = _rods(result)
    traj = result.get("trajectory")
    tip = (np.asarray(traj["tip_position"], dtype=float)
           if traj and "tip_position" in traj else None)
    a, b = _view(np.vstack(rods + ([tip] if tip is not None else [])))
    if ax is None:
        _, ax = plt.subplots(figsize=(6, 5))
    for i, nodes in enumerate(rods):
        ax.plot(nodes[:, a], nodes[:, b], "-", lw=2, color="C0",
                label="rod" if i == 0 else None)
        ax.plot(nodes[0, a], nodes[0, b], "ks", ms=6, label="base" if i == 0 else None)
    for i, body in enumerate(result.get("assembly", {}).get("bodies", [])):
        p = np.asarray(body["position"], dtype=float)
        ax.plot(p[a], p[b], "o", color="C3", ms=7, label="body" if i == 0 else None)
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
    """Writes an animation of a dynamics run (a rod or an assembly) to `path`: GIF through
    Pillow for a .gif path, video through ffmpeg for .mp4 (or .mov, .mkv, .webm, .avi). `out` is
    cosserat.solve(problem, nodes=True) of a dynamics problem (its "frames"); `every` keeps every
    n-th frame; fps > 0. Returns the number of frames written."""
    import os
    frames = out.get("frames")
    if frames is None:
        raise ValueError("animate: needs cosserat.solve(problem, nodes=True) of a dynamics problem "
                         "(its output has no \"frames\")")
    if isinstance(every, bool) or not isinstance(every, (int, np.integer)) or every < 1:
        raise ValueError(f"every: expected a whole number >= 1, got {every!r}")
    if not (isinstance(fps, (int, float, np.integer, np.floating)) and np.isfinite(fps) and fps > 0):
        raise ValueError(f"fps: expected a number > 0, got {fps!r}")
    extension = os.path.splitext(os.fspath(path))[1].lower()
    if extension not in (".gif",) + _VIDEO:
        raise ValueError(f"path: expected a {', '.join(('.gif',) + _VIDEO)} file, "
                         f"got {os.fspath(path)!r}")
    plt = _pyplot()
    from matplotlib import animation
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    if extension in _VIDEO and not animation.FFMpegWriter.isAvailable():
        raise RuntimeError("animate: MP4 needs ffmpeg (apt install ffmpeg); a .gif path "
                           "uses Pillow instead")
    t = frames["t"][::every]
    rods = [r[::every] for r in frames["rods"]] if "rods" in frames \
        else [frames["position"][::every]]
    everything = np.concatenate([r.reshape(-1, 3) for r in rods])
    a, b = _view(everything)
    fig, ax = plt.subplots(figsize=(6, 5))
    try:
        lo, hi = everything.min(axis=0), everything.max(axis=0)
        pad = 0.05 * max(hi[a] - lo[a], hi[b] - lo[b], 1e-9)
        ax.set_xlim(lo[a] - pad, hi[a] + pad)
        ax.set_ylim(lo[b] - pad, hi[b] + pad)
        ax.set_aspect("equal")
        ax.set_xlabel("xyz"[a] + " [m]")
        ax.set_ylabel("xyz"[b] + " [m]")
        ax.grid(True, alpha=0.3)
        lines = [ax.plot([], [], "-", lw=2, color="C0")[0] for _ in rods]
        label = ax.text(0.02, 0.95, "", transform=ax.transAxes)

        def draw(k):
            for line, r in zip(lines, rods):
                line.set_data(r[k][:, a], r[k][:, b])
            label.set_text(f"t = {t[k]:.3f} s")
            return (*lines, label)

        anim = animation.FuncAnimation(fig, draw, frames=len(t), blit=True)
        # WebM holds VP8/VP9/AV1 only; the other containers take matplotlib's H.264.
        writer = (animation.PillowWriter(fps=fps) if extension == ".gif"
                  else animation.FFMpegWriter(fps=fps, codec="libvpx-vp9")
                  if extension == ".webm" else animation.FFMpegWriter(fps=fps))
        anim.save(os.fspath(path), writer=writer)
    finally:
        plt.close(fig)
    return len(t)
