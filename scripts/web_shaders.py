#!/usr/bin/env python3
"""The browser edition's shader tree: every stage file of a GLSL 3.30 core tree, its includes
expanded (tree-relative, as src/gl/shader_library.cpp resolves them), checked by glslang and
translated mechanically to ESSL 3.00 (glslangValidator -> SPIR-V -> spirv-cross). The output
is what WebGL 2 compiles; a student can open it beside the original.

usage: web_shaders.py TREE_DIR OUT_DIR
"""
import pathlib
import re
import subprocess
import sys
import tempfile

INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"\s*$')
# glBindAttribLocation decides vertex inputs, as on the desktop: the locations glslang's
# --auto-map-locations gave them in declaration order are dropped.
INPUT_LOCATION = re.compile(r'^layout\(location = \d+\) in ', re.M)


def expand(root, path, depth=0):
    if depth > 16:
        sys.exit(f"web_shaders: {path}: #include nested too deeply")
    lines = []
    for line in path.read_text().splitlines():
        m = INCLUDE.match(line)
        lines.append(expand(root, root / m.group(1), depth + 1) if m else line)
    return "\n".join(lines)


def translate(root, source, out):
    with tempfile.TemporaryDirectory() as tmp:
        expanded = pathlib.Path(tmp) / ("shader" + source.suffix)
        expanded.write_text(expand(root, source) + "\n")
        spirv = pathlib.Path(tmp) / "shader.spv"
        check = subprocess.run(["glslangValidator", "-G", "--aml", "--amb", "-o", str(spirv),
                                str(expanded)], capture_output=True, text=True)
        if check.returncode != 0:
            sys.exit(f"web_shaders: {source}: glslang refused it:\n{check.stdout}{check.stderr}")
        essl = subprocess.run(["spirv-cross", "--es", "--version", "300", str(spirv)],
                              capture_output=True, text=True, check=True).stdout
    if source.suffix == ".vert":
        essl = INPUT_LOCATION.sub("in ", essl)
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(essl)


def main():
    root, out_dir = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
    sources = sorted(p for p in root.rglob("*") if p.suffix in (".vert", ".frag"))
    for source in sources:
        translate(root, source, out_dir / source.relative_to(root))
    print(f"web_shaders: {len(sources)} files translated to ESSL 3.00 in {out_dir}")


if __name__ == "__main__":
    main()
