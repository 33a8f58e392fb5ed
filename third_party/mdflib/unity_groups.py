#!/usr/bin/env python3
"""Writes unity_groups.cmake: mdflib's sources in batches of up to 16 that share no file-local
name (an anonymous namespace's or a static's, or a using-directive), so that each batch compiles
as one file. Run again after updating mdflib; files in SKIP compile on their own."""
import collections, glob, os, re

HERE = os.path.dirname(os.path.abspath(__file__))
SKIP = set(open(os.path.join(HERE, "unity_skip.txt")).read().split()) if os.path.exists(os.path.join(HERE, "unity_skip.txt")) else set()
files = sorted(os.path.basename(f) for f in glob.glob(os.path.join(HERE, "src", "*.cpp")))
names = collections.defaultdict(set)
for f in files:
    depth, anon = 0, None
    for line in open(os.path.join(HERE, "src", f), encoding="utf-8", errors="replace").read().split("\n"):
        s = line.strip()
        if re.match(r"^namespace\s*\{", s) and anon is None:
            anon = depth
        if s.startswith("using namespace"):
            names[f].add(s)
        elif (anon is not None and depth == anon + 1) or (depth <= 1 and s.startswith("static ")):
            m = re.match(r"^(?:static\s+|inline\s+|constexpr\s+|const\s+)*[\w:<>,\s\*&]+?\b(\w+)\s*(\(|=|\[|\{|;)", line) \
                if line[:1] not in " \t/}#" else None
            if m:
                names[f].add(m.group(1))
        depth += line.count("{") - line.count("}")
        if anon is not None and depth <= anon:
            anon = None
groups = []
for f in files:
    if f in SKIP:
        continue
    for g in groups:
        if len(g) < 16 and not any(names[f] & names[o] for o in g):
            g.append(f)
            break
    else:
        groups.append([f])
with open(os.path.join(HERE, "unity_groups.cmake"), "w") as out:
    out.write("# Written by unity_groups.py: mdflib's sources in unity batches that share no file-local name.\n")
    for i, g in enumerate(groups):
        out.write("set_source_files_properties(%s\n  PROPERTIES UNITY_GROUP mdf%d)\n" % (" ".join("src/" + f for f in g), i))
    if SKIP:
        out.write("set_source_files_properties(%s\n  PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)\n" % " ".join("src/" + f for f in sorted(SKIP)))
print(len(groups), "groups,", len(SKIP), "files alone")
