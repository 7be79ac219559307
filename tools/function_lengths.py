#!/usr/bin/env python3
"""The longest function bodies in C++ sources, by counting braces.

Usage: python3 tools/function_lengths.py [--most N] [PATH...]   (default: src, 10)

A function is a brace block opened at namespace or class scope whose header (the text since
the previous ';', '{' or '}') holds a ')': lambdas and blocks inside it count as its lines.
Comments, string and character literals are blanked first. The length counts the lines from
the first of the declaration (a template line included) to the closing brace. Crude (macros
and raw strings are not parsed), but good enough to find routines too long to read.
"""
import argparse
import pathlib
import re


def blank(text):
    """Comments, strings and character literals replaced by spaces (newlines kept)."""
    pattern = re.compile(r'//[^\n]*|/\*.*?\*/|"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'', re.S)
    return pattern.sub(lambda m: re.sub(r"[^\n]", " ", m.group(0)), text)


def functions(path):
    text = blank(path.read_text(errors="replace"))
    scopes = []  # 'ns', 'class', 'fn', 'other' for each open brace
    header_start = 0
    found = []
    for i, ch in enumerate(text):
        if ch in ";{}" and "fn" not in scopes:
            header = text[header_start:i]
        if ch == "{":
            if "fn" in scopes:
                scopes.append("other")
            else:
                kind = "other"
                if re.search(r"\bnamespace\b", header) or re.search(r'\bextern\s*$', header):
                    kind = "ns"
                elif ")" in header and not re.search(r"=\s*$", header):
                    kind = "fn"
                elif re.search(r"\b(class|struct|union|enum)\b", header):
                    kind = "class"
                scopes.append(kind)
                if kind == "fn":
                    bare = re.sub(r"\[\[.*?\]\]", " ", header, flags=re.S)  # attributes
                    name = re.findall(r"[~\w:<>]+", bare[: bare.find("(")])
                    lead = len(header) - len(header.lstrip())
                    start = text.count("\n", 0, header_start + lead) + 1
                    found.append([name[-1] if name else "?", start, None])
            header_start = i + 1
        elif ch == "}":
            kind = scopes.pop() if scopes else "other"
            if kind == "fn":
                found[-1][2] = text.count("\n", 0, i) + 1
            if "fn" not in scopes:
                header_start = i + 1
        elif ch == ";" and "fn" not in scopes:
            header_start = i + 1
    return [(end - start + 1, name, start) for name, start, end in found if end]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("paths", nargs="*", default=["src"])
    parser.add_argument("--most", type=int, default=10)
    args = parser.parse_args()
    rows = []
    for root in args.paths:
        root = pathlib.Path(root)
        files = [root] if root.is_file() else sorted(root.rglob("*.[ch]pp"))
        for f in files:
            rows += [(n, name, f"{f}:{line}") for n, name, line in functions(f)]
    for n, name, where in sorted(rows, reverse=True)[: args.most]:
        print(f"{n:5d}  {name:<32} {where}")


if __name__ == "__main__":
    main()
