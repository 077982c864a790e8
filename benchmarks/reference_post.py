"""A hand-written post for the throughput benchmark: the least a post for the roughing file
must do, written as a shop would write a one-off (a dict for the state, f-strings).

It reads APT text (continuations, comments), keeps X, Y, Z, G and F modal, numbers the
blocks, rounds to 0.0001 mm, and turns RAPID, FEDRAT, CIRCLE and GOTO into G0/G1/G2/G3
lines. It knows nothing else (no machine data, segmentation, feed commands, listing or
diagnostics), so its rate is a ceiling for any post written in Python, not a goal to copy.

    python benchmarks/reference_post.py SOURCE TARGET
"""

import sys


def main(source: str, target: str) -> None:
    state: dict[str, object] = {"x": None, "y": None, "z": None, "g": None, "f": None}
    feed = 0.0
    rapid = False
    circle: tuple[float, float, bool] | None = None
    number = 0
    pending = ""
    with open(source) as lines, open(target, "w") as out:
        write = out.write
        for line in lines:
            if pending:
                line = pending + line
                pending = ""
            stripped = line.rstrip()
            if stripped.endswith("$") and not stripped.startswith("$$"):
                pending = stripped[:-1]
                continue
            if line.startswith("$$"):
                continue
            major, _, rest = line.partition("/")
            major = major.strip()
            if major == "GOTO":
                x, y, z = (float(value) for value in rest.split(",")[:3])
                sx, sy, sz = round(x * 10000), round(y * 10000), round(z * 10000)
                number += 1
                words = [f"N{number}"]
                if rapid:
                    g = "G0"
                elif circle is not None:
                    g = "G2" if circle[2] else "G3"
                else:
                    g = "G1"
                if g != state["g"]:
                    words.append(g)
                    state["g"] = g
                if sx != state["x"]:
                    words.append(f"X{sx / 10000:.4f}")
                    state["x"] = sx
                if sy != state["y"]:
                    words.append(f"Y{sy / 10000:.4f}")
                    state["y"] = sy
                if sz != state["z"]:
                    words.append(f"Z{sz / 10000:.4f}")
                    state["z"] = sz
                if circle is not None:
                    words.append(f"I{circle[0]:.4f} J{circle[1]:.4f}")
                    circle = None
                if not rapid and feed != state["f"]:
                    words.append(f"F{feed:.1f}")
                    state["f"] = feed
                rapid = False
                write(" ".join(words) + "\n")
            elif major == "RAPID":
                rapid = True
            elif major == "FEDRAT":
                feed = float(rest.split(",")[0])
            elif major == "CIRCLE":
                values = [float(value) for value in rest.split(",")]
                circle = (values[0], values[1], values[5] < 0)
            elif major == "FINI":
                write("M2\n")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
