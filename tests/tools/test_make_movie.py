#!/usr/bin/python3
"""ctest tools.MakeMovie.TheLastWingbeatAsAnMp4: `make movie CASE=x.toml` on a short run
(flat plate, rigid, 3 x 4 panels, 50 steps a wingbeat, 1 wingbeat, a frame every step;
run first with flapsim into the folder make uses, so make only renders) at 320 x 180 writes
RUN/movie.mp4: ffprobe reads it as H.264 with at least 50 frames (the last wingbeat's 51
frames, t/T 0 … 1), and in every 10th frame (extracted with ffmpeg) the wing is there: the
pixels off the white background, after an erosion that removes the wake's and the chain's
1-2 pixel lines, cover at least 2 % of the picture away from the scalar bars (the right
16 %) and the caption (the bottom 10 %)."""
import glob
import os
import subprocess
import sys


import tool_test_args

a, work = tool_test_args.arguments("flapsim", "source", "work")
case = tool_test_args.write_flapping_plate_case(a.source, os.path.join(work, "movie_plate.toml"), "movie_plate", 50, 1, 1)
out = os.path.join(work, "out")
run = os.path.join(out, "movie_plate")
tool_test_args.run_case(a.flapsim, case, run)
check = tool_test_args.Checks()
failures = check.failures


r = subprocess.run(["make", "-C", a.source, "--no-print-directory", "movie", f"CASE={case}", f"OUT={out}",
                    "MOVIE_SIZE=320 180"], capture_output=True, text=True)
print(r.stdout[-1500:], r.stderr[-1500:])
check(r.returncode == 0, f"make movie exited {r.returncode}")
movie = os.path.join(run, "movie.mp4")
check(os.path.isfile(movie), f"no {movie}")
if os.path.isfile(movie):
    probe = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                            "stream=codec_name,nb_read_frames,width,height", "-of", "default=nw=1", movie],
                           capture_output=True, text=True).stdout
    info = dict(line.split("=", 1) for line in probe.split())
    print(f"ffprobe: {info}")
    check(info.get("codec_name") == "h264", f"codec {info.get('codec_name')}, expected h264")
    check(int(info.get("nb_read_frames", 0)) >= 50, f"{info.get('nb_read_frames')} frames, expected >= 50")
    frames = os.path.join(work, "frames")
    os.makedirs(frames)
    subprocess.run(["ffmpeg", "-loglevel", "error", "-i", movie, "-vf", r"select=not(mod(n\,10))", "-vsync", "0",
                    os.path.join(frames, "f_%03d.png")], check=True)
    sampled = sorted(glob.glob(os.path.join(frames, "*.png")))
    check(len(sampled) >= 5, f"{len(sampled)} sampled frames, expected >= 5")
    for png in sampled:
        rgb = tool_test_args.read_png_rgb(png)
        h, w, _ = rgb.shape
        rgb = rgb[::-1]  # VTK's rows start at the bottom
        inked = (rgb < 0.85).any(axis=2)[: int(0.9 * h), : int(0.84 * w)]
        core = inked.copy()  # 2 erosions by the 3 x 3 cross
        for _ in range(2):
            core[1:-1, 1:-1] = (core[1:-1, 1:-1] & core[:-2, 1:-1] & core[2:, 1:-1]
                                & core[1:-1, :-2] & core[1:-1, 2:])
            core[0, :] = core[-1, :] = False
            core[:, 0] = core[:, -1] = False
        share = core.mean()
        print(f"{os.path.basename(png)}: wing {100 * share:.1f} % of the picture")
        check(share >= 0.02, f"{os.path.basename(png)}: the wing covers {100 * share:.2f} %, expected >= 2 %")
sys.exit(1 if failures else 0)
