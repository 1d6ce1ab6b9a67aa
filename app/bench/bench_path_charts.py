"""The charts of a bench that replayed a camera path (`raylab bench --camera-path`, issue 37), drawn by
bench_charts.py beside its others: for every scene and path, the frame time (work ms, median over the
rounds) and the prediction error (mean over bounces >= 1, from the detailed replay) against the path
frame, one line per cell, cuts marked. Reads DIR/motion.json, which the bench writes from path_frames.jsonl."""
import json
import os
import re

from checked_write import write_with  # app/checked_write.py (bench_charts.py puts app/ on the path)


def safe(text):
    """A path or scene name as part of a file name: a file path's stem, anything but [A-Za-z0-9._-] as '-'."""
    if text.lower().endswith(".json"):
        text = os.path.splitext(os.path.basename(text))[0]
    return re.sub(r"[^A-Za-z0-9._-]+", "-", text).strip("-")


def load_motion(folder):
    path = os.path.join(folder, "motion.json")
    if not os.path.exists(path):
        return None
    with open(path) as f:
        return json.load(f)


def motion_chart(plt, cells, key, ylabel, title, path):
    fig, ax = plt.subplots(figsize=(9, 4.5))
    drawn = 0
    for c in cells:
        values = c[key]
        xs = [f for f, v in enumerate(values) if v is not None]
        if not xs:
            continue
        ax.plot(xs, [values[f] for f in xs], lw=1.0, marker="." if len(xs) < 40 else None, label=c["label"])
        drawn += 1
    for f in cells[0]["cuts"]:
        ax.axvline(f, color="grey", ls=":", lw=0.8)
    ax.set_xlabel("path frame (dotted: a cut)")
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize=9)
    if drawn:
        ax.legend(fontsize=6, ncol=2)
    else:
        ax.text(0.5, 0.5, "no cell measured it", transform=ax.transAxes, ha="center")
    fig.tight_layout()
    write_with(path, lambda f: fig.savefig(f, dpi=110, format="png"))
    plt.close(fig)


def path_charts(plt, folder, device=""):
    """Draws motion_frame_ms_SCENE-PATH.png and motion_prediction_error_SCENE-PATH.png; returns
    {(scene, camera_path): [their paths]} (the study's report links them)."""
    motion = load_motion(folder)
    if not motion:
        return {}
    groups = {}
    for c in motion["cells"]:
        groups.setdefault((c["scene"], c["camera_path"]), []).append(c)
    written = {}
    for (scene, camera_path), cells in groups.items():
        name = f"{safe(scene)}-{safe(camera_path)}"
        about = f"{scene} along {camera_path}, {cells[0]['frames']} frames{', ' + device if device else ''}"
        rounds = max(c["rounds"] for c in cells)
        charts = [os.path.join(folder, f"motion_{what}_{name}.png") for what in ("frame_ms", "prediction_error")]
        motion_chart(plt, cells, "frame_ms", "GPU work time per frame (ms)",
                     f"Frame time along the path\n{about} (median of {rounds} round{'s' if rounds != 1 else ''})",
                     charts[0])
        motion_chart(plt, cells, "prediction_error", "prediction error / scene diagonal\n(mean over bounces >= 1)",
                     f"Prediction error along the path\n{about} (the detailed replay)",
                     charts[1])
        print(f"motion charts for {name} in {folder}")
        written[(scene, camera_path)] = charts
    return written
