#!/usr/bin/env bash
# A lesson's worksheet as a reader sees it: the PDF written by `newtonlab lesson
# --worksheet --key`, turned back into text by poppler's pdftotext, holds the title, the
# instructions, every question's prompt, and an answer key whose value theory predicts:
# the disc rolls 2 m down 20° in sqrt(2·2 m / (g sin 20° / 1.5)) = 1.337 s.
set -euo pipefail
cd "$(dirname "$0")/.."
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
target/release/newtonlab lesson example:lesson-galileo-incline --worksheet "$out/w.pdf" --key
text=$(pdftotext -layout "$out/w.pdf" -)
pages=$(pdfinfo "$out/w.pdf" | awk '/^Pages:/ {print $2}')
for words in "Galileo's incline" "Name:" "Which arrives first" "Guess first" \
    "How long does the disc take to roll 2 m along the slope?" \
    "How fast is the disc going after 2 m?" "You may change" \
    "Answer key: Galileo's incline" "disc_time: 1.337 s" "ring_time: 1.544 s"; do
    if ! grep -qF "$words" <<<"$text"; then
        echo "worksheet: '$words' is not in the PDF's text:" >&2
        echo "$text" >&2
        exit 1
    fi
done
[ "$pages" -ge 2 ] || { echo "worksheet: $pages page(s); the key needs its own" >&2; exit 1; }
echo "worksheet: $pages pages; title, instructions, questions and the key read back"
