#!/bin/sh
# Fixture of the archive checks: the default island as a world file, exported to PMTiles and
# MBTiles by the real program, for tests/node/check_pmtiles*.mjs and tests/cli/check_mbtiles.py.
# Usage: write_export_archives.sh STRAHLER DIR MINZOOM MAXZOOM
set -eu
strahler=$1 dir=$2 minzoom=$3 maxzoom=$4
rm -rf "$dir"
mkdir -p "$dir"
STRAHLER_CACHE_DIR="$dir/cache" "$strahler" generate --quiet -o "$dir/world.world"
"$strahler" export "$dir/world.world" --zooms "$minzoom-$maxzoom" --threads 2 --quiet -o "$dir/world.pmtiles"
"$strahler" export "$dir/world.world" --zooms "$minzoom-$maxzoom" --threads 2 --quiet -o "$dir/world.mbtiles"
# The vector tiles (gzipped MVT) of a few zooms, for the same readers.
"$strahler" export "$dir/world.world" --zooms 8-10 --tile mvt --threads 2 --quiet -o "$dir/world-vector.pmtiles"
"$strahler" export "$dir/world.world" --zooms 8-10 --tile mvt --threads 2 --quiet -o "$dir/world-vector.mbtiles"
# A layer's grey PNG tiles (bush density) of a few zooms, for the same readers.
"$strahler" export "$dir/world.world" --zooms 9-11 --layer vegetation --species bush --threads 2 --quiet -o "$dir/world-layer.pmtiles"
"$strahler" export "$dir/world.world" --zooms 9-11 --layer vegetation --species bush --threads 2 --quiet -o "$dir/world-layer.mbtiles"
