#!/usr/bin/env bash
# Prints DXF drawings to PDF with LibreCAD's command-line dxf2pdf (Debian `librecad`, headless
# through Qt's offscreen platform) and the PDFs to PNG with pdftoppm (poppler-utils), to look at
# the drawings as a CAD program shows them, text included:
#   scripts/dxf-to-pdf.sh OUT_DIR FILE.dxf...
# Writes OUT_DIR/NAME.pdf (A3 landscape, drawing fitted within 10 mm margins) and OUT_DIR/NAME.png (100 dpi) per file.
set -euo pipefail
out=${1:?usage: dxf-to-pdf.sh OUT_DIR FILE.dxf...}
shift
for tool in librecad pdftoppm; do
  command -v "$tool" >/dev/null || { echo "dxf-to-pdf: $tool is not installed (scripts/setup-deps.sh)" >&2; exit 2; }
done
mkdir -p "$out"
export QT_QPA_PLATFORM=offscreen XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-$(mktemp -d)}
for dxf in "$@"; do
  name=$(basename "${dxf%.dxf}")
  # -o keeps only the file name (the PDF lands beside the DXF); -t names the folder.
  # -f: 10 mm paper margins, so the drawing frame (io::add_frame) that -a fits to the page is printed whole.
  timeout 120 librecad dxf2pdf -a -f 10,10,10,10 -p 420x297 -t "$(realpath "$out")" "$(realpath "$dxf")" >/dev/null 2>&1
  [ -s "$out/$name.pdf" ] || { echo "dxf-to-pdf: LibreCAD wrote no PDF for $dxf" >&2; exit 1; }
  pdftoppm -png -r 100 -singlefile "$out/$name.pdf" "$out/$name"
done
