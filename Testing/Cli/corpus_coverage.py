#!/usr/bin/python3
"""What a stratified sample of the hostile corpus covers, against a full run of the same runner.

    corpus_coverage.py FULL_WORK_DIR SAMPLE_WORK_DIR [PROGRAM_PREFIX]

FULL_WORK_DIR holds the results.json of a run over the whole corpus (hostile_corpus.py without
--sample), SAMPLE_WORK_DIR that of a --sample run of the same runner; PROGRAM_PREFIX is what the
runner's lines start with ("stylize_dataset.py: " for python, "vtkstylize: " for cli, nothing
for paraview). It prints, per outcome and kind of message (corpus_common.message_kind: the line
with names and numbers taken out), how many cases of the full run and of the sample have it, and
per extension (reader) the same; and it exits 1 if a kind of refusal, of warning or a reader of
the full run has no case in the sample. For docs/testing.md, after the corpus or the messages
change:

    hostile_corpus.py --runner python stylize_dataset.py build/Testing/Cli/data /tmp/full
    corpus_coverage.py /tmp/full build/Testing/Cli/hostile_python "stylize_dataset.py: "
"""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from corpus_common import extension, message_kind  # noqa: E402


def load(work):
    return json.load(open(os.path.join(work, "results.json")))


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    full, sample = load(sys.argv[1]), load(sys.argv[2])
    prefix = sys.argv[3] if len(sys.argv) > 3 else ""

    def kinds(results):
        counts = {}
        for case in results:
            key = (case["kind"], message_kind(case["lines"], prefix, case["file"]) or
                   "(no message)")
            counts[key] = counts.get(key, 0) + 1
        return counts

    def readers(results):
        counts = {}
        for case in results:
            counts[extension(case["file"])] = counts.get(extension(case["file"]), 0) + 1
        return counts

    full_kinds, sample_kinds = kinds(full), kinds(sample)
    print("| outcome | kind of message | full run | sample |")
    print("|---|---|---:|---:|")
    for key in sorted(full_kinds, key=lambda k: (k[0], -full_kinds[k], k[1])):
        print("| %s | %s | %d | %d |" % (key[0], key[1].replace("|", "/")[:140], full_kinds[key],
                                          sample_kinds.get(key, 0)))
    full_readers, sample_readers = readers(full), readers(sample)
    print("| reader (extension) | full run | sample |")
    print("|---|---:|---:|")
    for ext in sorted(full_readers):
        print("| %s | %d | %d |" % (ext or "(none)", full_readers[ext], sample_readers.get(ext, 0)))
    missing = [k for k in full_kinds if k not in sample_kinds]
    missing_readers = [e for e in full_readers if e not in sample_readers]
    extra = [k for k in sample_kinds if k not in full_kinds]
    print("%d cases, %d kinds and %d readers in the full run; %d cases in the sample: %d kinds "
          "missing, %d readers missing, %d kinds only in the sample" % (
              len(full), len(full_kinds), len(full_readers), len(sample), len(missing),
              len(missing_readers), len(extra)))
    for key in missing:
        print("missing: %s: %s (%d cases)" % (key[0], key[1], full_kinds[key]))
    for ext in missing_readers:
        print("missing reader: %s" % ext)
    return 1 if missing or missing_readers else 0


if __name__ == "__main__":
    sys.exit(main())
