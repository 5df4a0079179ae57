#!/usr/bin/env bash
# Makes the timing test media from the GRID demo clips (Debian 12's ffmpeg 5.1). Run from this
# folder: bash make.sh. See README.md for what each file is for.
set -euo pipefail
demo=../../../../resources/demo/media
V=(-c:v libx264 -preset veryfast -crf 40 -pix_fmt yuv420p)
A=(-c:a aac -b:a 64k -ac 1)
ff() { ffmpeg -v error -y "$@"; }
# The clean original, re-encoded as the variants are.
ff -i "$demo/bbaf2n.mpg" "${V[@]}" "${A[@]}" clean.mp4
# The sound starts 0.5 s after the picture (a stream start offset).
ff -i "$demo/bbaf2n.mpg" -itsoffset 0.5 -i "$demo/bbaf2n.mpg" -map 0:v -map 1:a "${V[@]}" "${A[@]}" audio_late_0.5s.mp4
# Every fourth frame and frames 30-37 dropped, the rest at their own times (variable frame rate).
ff -i "$demo/bbaf2n.mpg" -vf "select='not(eq(mod(n\,4)\,3))*not(between(n\,30\,37))'" -fps_mode vfr \
   "${V[@]}" "${A[@]}" vfr.mp4
# 30000/1001 frames per second.
ff -i "$demo/bbaf2n.mpg" -vf fps=30000/1001 "${V[@]}" "${A[@]}" ntsc_29.97fps.mp4
# The sound ends after 2.0 s, the picture after 3.0 s.
ff -i "$demo/bbaf2n.mpg" -af atrim=0:2.0 "${V[@]}" "${A[@]}" audio_short_2s.mp4
# Three clips joined by stream copy: each clip's sound (cut to 2.952 s) starts with its picture at
# 0, 3 and 6 s, leaving a 48 ms timestamp gap before each join.
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
: > "$tmp/list.txt"
for clip in bbaf2n bgin3a bwbg8n; do
  ff -i "$demo/$clip.mpg" "${V[@]}" -af atrim=0:2.952 -c:a flac -ar 16000 -ac 1 "$tmp/$clip.mkv"
  echo "file '$tmp/$clip.mkv'" >> "$tmp/list.txt"
done
ff -f concat -safe 0 -i "$tmp/list.txt" -c copy joined_gaps_48ms.mkv
# The joined sound as a player presents it: ffmpeg fills every timestamp gap of 1 ms or more.
ff -i joined_gaps_48ms.mkv -vn -af aresample=async=1:min_hard_comp=0.001:first_pts=0 -c:a flac -ar 16000 -ac 1 \
   joined_presented.flac
for clip in bbaf2n bgin3a bwbg8n; do
  tr -d '\r' < "$demo/$clip.align" | awk '$3 != "sil" && $3 != "sp" { printf "%s ", $3 }'
done | sed 's/ $//' > joined.txt
echo >> joined.txt
