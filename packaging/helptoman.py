#!/usr/bin/env python3
"""Turn a program's --help text into a gzipped man page (troff, man macros).

The man pages are generated from the programs' own --help output so that the help text is
written once. The layout is that of QCommandLineParser::helpText():

    Usage: NAME [options] ARGS
    Description line(s).
                                        (blank)
    Section:                            a heading; its entries are indented by two spaces,
      tag   text                        tag and text on one line, or the text on the following
      tag                               lines, indented deeper (continuations of the text)
          text
    Heading: text                       a one-paragraph section ("Exit codes: 0 ok, ...")

Anything else becomes a plain paragraph. The output is reproducible: the date is given, the
gzip header carries no name and no time.
"""

import argparse
import gzip
import os
import re
import subprocess
import sys

ENTRY = re.compile(r"^  (\S.*)$")
TAG_AND_TEXT = re.compile(r"^(\S.*?)\s{2,}(\S.*)$")
HEADING = re.compile(r"^([A-Z][^:]*):$")
HEADED_PARAGRAPH = re.compile(r"^([A-Z][A-Za-z ]*): (.+)$")


def run(program, name, arg):
    """Runs the program as NAME (its argv[0]), so that its usage line shows the bare name."""
    env = dict(os.environ, QT_QPA_PLATFORM="offscreen")
    result = subprocess.run([name, arg], executable=program, env=env, capture_output=True,
                            text=True, timeout=60, check=False)
    if result.returncode != 0 or not result.stdout.strip():
        sys.exit(f"helptoman: '{program} {arg}' failed (exit {result.returncode}): "
                 f"{result.stderr.strip()}")
    return result.stdout


def escape(text):
    """Escapes text for troff: backslashes, minus signs (so that options copy and paste), and a
    leading dot or quote that would be read as a request."""
    text = text.replace("\\", "\\e").replace("-", "\\-")
    if text.startswith((".", "'")):
        text = "\\&" + text
    return text


def format_tag(tag):
    """Bold for the literal words (options, the command name), italic for placeholders
    (<ms>, URI, INDEX:SUB), roman for the rest."""
    words = []
    for i, word in enumerate(tag.split(" ")):
        bare = word.strip("[],|")
        if bare.startswith("-") or (i == 0 and not bare.isupper()):
            words.append("\\fB" + escape(word) + "\\fR")
        elif word.startswith("<") or (bare and bare.replace(":", "").isupper()):
            words.append("\\fI" + escape(word) + "\\fR")
        else:
            words.append(escape(word))
    return " ".join(words)


def parse(help_text):
    """Returns (synopsis, description paragraphs, [(heading, entries or paragraph)])."""
    lines = help_text.rstrip("\n").split("\n")
    usage = lines.pop(0)
    if not usage.startswith("Usage: "):
        sys.exit(f"helptoman: the help text does not start with 'Usage: ': {usage!r}")
    synopsis = usage[len("Usage: "):].split(" ", 1)
    description = []
    while lines and lines[0].strip():
        description.append(lines.pop(0).strip())
    sections = []
    for line in lines:
        if not line.strip():
            continue
        if match := HEADING.match(line):
            sections.append((match.group(1), []))
        elif match := ENTRY.match(line):
            if not sections:
                sys.exit(f"helptoman: an indented line outside a section: {line!r}")
            entries = sections[-1][1]
            if match := TAG_AND_TEXT.match(match.group(1)):
                entries.append([match.group(1), match.group(2)])
            else:
                entries.append([line.strip(), ""])
        elif line.startswith("   ") and sections and sections[-1][1]:
            entry = sections[-1][1][-1]
            entry[1] = (entry[1] + " " + line.strip()).strip()
        elif match := HEADED_PARAGRAPH.match(line):
            sections.append((match.group(1), match.group(2)))
        else:
            sections.append(("", line.strip()))
    return synopsis, description, sections


def troff(name, version, date, synopsis, description, sections, see_also):
    summary = description[0].rstrip(".") if description else name
    out = [f'.TH {name.upper()} 1 "{date}" "{escape(version)}" "User Commands"',
           ".SH NAME", f"{escape(name)} \\- {escape(summary)}",
           ".SH SYNOPSIS", f".B {escape(synopsis[0])}"]
    if len(synopsis) > 1:
        out.append(format_tag("x " + synopsis[1]).split(" ", 1)[1])
    out.append(".SH DESCRIPTION")
    out.extend(escape(line) for line in description)
    for heading, body in sections:
        if heading:
            out.append(f'.SH "{heading.upper()}"')
        else:
            out.append(".PP")
        if isinstance(body, str):
            out.append(escape(body))
            continue
        for tag, text in body:
            out.extend([".TP", format_tag(tag)])
            if text:
                out.append(escape(text))
    if see_also:
        out.append('.SH "SEE ALSO"')
        out.append(",\n".join(f".BR {escape(page)} (1)" for page in see_also))
    return "\n".join(out) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n", 1)[0])
    parser.add_argument("--program", required=True, help="the built program to run")
    parser.add_argument("--name", required=True, help="its installed name")
    parser.add_argument("--date", required=True, help="the page's date, e.g. 2026-11-26")
    parser.add_argument("--see-also", default="", help="comma-separated page names")
    parser.add_argument("--output", required=True, help="the .1.gz file to write")
    args = parser.parse_args()

    synopsis, description, sections = parse(run(args.program, args.name, "--help"))
    version = run(args.program, args.name, "--version").strip().splitlines()[0]
    see_also = [page for page in args.see_also.split(",") if page and page != args.name]
    page = troff(args.name, version, args.date, synopsis, description, sections, see_also)

    # Written beside and renamed, so that an interrupted build never leaves half a page.
    partial = args.output + ".part"
    with open(partial, "wb") as raw:
        with gzip.GzipFile(filename="", mode="wb", compresslevel=9, fileobj=raw, mtime=0) as gz:
            gz.write(page.encode("utf-8"))
    os.replace(partial, args.output)


if __name__ == "__main__":
    main()
