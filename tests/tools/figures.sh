#!/bin/sh
# figures.sh - make figures: the divergence against the growth G, from
# the inhibition model itself (Douady and Couder's bifurcation diagram):
# for each G, the divergences of the last third of the primordia, with
# G falling slowly from fast growth (start = 2), and held fixed from the
# first two primordia (transient = 0), where other modes appear.
# Writes $FIGURES/divergence.svg.
: "${PHYLLO:=./phyllo-export}" "${FIGURES:=build/figures}"
mkdir -p "$FIGURES" || exit 1
tmp=$FIGURES/divergence.dat
: >"$tmp"
for series in falling fixed; do
	for G in 3 2 1.5 1.2 1 0.8 0.65 0.5 0.4 0.32 0.26 0.2 0.16 0.13 0.1 \
	    0.08 0.065 0.05 0.04 0.032 0.026 0.02 0.016 0.013 0.01 0.008 \
	    0.0065 0.005 0.004 0.0032 0.0026 0.002 0.0016 0.0013 0.001 \
	    0.0008 0.00065 0.0005; do
		N=$(echo "$G" | awk '{ n = int(2 / $1); n = n < 150 ? 150 : n > 900 ? 900 : n; if ($1 * n > 600) n = int(600 / $1); print n }')
		extra=
		[ $series = fixed ] && extra='transient = 0;'
		printf 'model = "inhibition";\ncount = %d;\ninhibition = { growth = %s; %s };\n' \
			"$N" "$G" "$extra" | "$PHYLLO" --csv - |
		awk -F, -v G="$G" -v s=$series 'NR > 1 { a[NR - 2] = atan2($4, $3) }
		END {
			n = NR - 1
			for (i = int(2 * n / 3); i < n; i++) {
				d = a[i] - a[i - 1]; pi = 3.141592653589793
				while (d > pi) d -= 2 * pi; while (d < -pi) d += 2 * pi
				if (d < 0) d = -d
				print s, G, d * 180 / pi
			}
		}' >>"$tmp" || exit 1
	done
done
awk '
BEGIN {
	W = 720; H = 420; L = 70; R = 20; T = 40; B = 50
	x0 = log(0.0005); x1 = log(3); y0 = 80; y1 = 190
	printf "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
	printf "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" viewBox=\"0 0 %d %d\" font-family=\"sans-serif\" font-size=\"12\">\n", W, H, W, H
	printf "<title>Divergence against growth G, from the inhibition model</title>\n"
	printf "<rect width=\"100%%\" height=\"100%%\" fill=\"#fff\"/>\n"
	printf "<text x=\"%d\" y=\"22\" font-size=\"14\">Divergence angle against growth G (phyllo-export, inhibition model, power law s = 3)</text>\n", L
	for (k = 0; k < 2; k++) { }
	# axes and grid
	n = split("0.0005 0.001 0.002 0.005 0.01 0.02 0.05 0.1 0.2 0.5 1 2", gx, " ")
	for (i = 1; i <= n; i++) {
		x = L + (log(gx[i]) - x0) / (x1 - x0) * (W - L - R)
		printf "<line x1=\"%.1f\" y1=\"%d\" x2=\"%.1f\" y2=\"%d\" stroke=\"#ddd\"/>\n", x, T, x, H - B
		printf "<text x=\"%.1f\" y=\"%d\" text-anchor=\"middle\">%s</text>\n", x, H - B + 16, gx[i]
	}
	n = split("90 99.5 120 137.5 160 180", gy, " ")
	for (i = 1; i <= n; i++) {
		y = T + (y1 - gy[i]) / (y1 - y0) * (H - T - B)
		printf "<line x1=\"%d\" y1=\"%.1f\" x2=\"%d\" y2=\"%.1f\" stroke=\"%s\"/>\n", L, y, W - R, y, gy[i] == 137.5 ? "#f0b0b0" : "#ddd"
		printf "<text x=\"%d\" y=\"%.1f\" text-anchor=\"end\">%s&#176;</text>\n", L - 6, y + 4, gy[i]
	}
	printf "<text x=\"%d\" y=\"%d\" text-anchor=\"middle\">G (log scale): radial growth a plastochron over the meristem radius</text>\n", (L + W - R) / 2, H - 12
	printf "<rect x=\"%d\" y=\"%d\" width=\"%d\" height=\"%d\" fill=\"none\" stroke=\"#444\"/>\n", L, T, W - L - R, H - T - B
	X0 = x0; X1 = x1; Y0 = y0; Y1 = y1
}
{
	x = L + (log($2) - X0) / (X1 - X0) * (W - L - R)
	if ($3 < Y0 || $3 > Y1) next
	y = T + (Y1 - $3) / (Y1 - Y0) * (H - T - B)
	printf "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"1.6\" fill=\"%s\" fill-opacity=\"0.5\"/>\n", x + ($1 == "fixed" ? 3 : -3), y, $1 == "fixed" ? "#c07010" : "#1060b0"
}
END {
	printf "<circle cx=\"%d\" cy=\"%d\" r=\"4\" fill=\"#1060b0\"/><text x=\"%d\" y=\"%d\">G falling slowly from 2 (the default)</text>\n", W - 330, T + 20, W - 320, T + 24
	printf "<circle cx=\"%d\" cy=\"%d\" r=\"4\" fill=\"#c07010\"/><text x=\"%d\" y=\"%d\">G fixed from the first two (transient = 0)</text>\n", W - 330, T + 40, W - 320, T + 44
	# Right, below the line: the default series sits on it further left.
	printf "<text x=\"%d\" y=\"%d\" fill=\"#b05050\" text-anchor=\"end\">golden angle 137.5&#176;</text>\n", W - R - 8, T + (Y1 - 137.5) / (Y1 - Y0) * (H - T - B) + 16
	print "</svg>"
}' "$tmp" >"$FIGURES/divergence.svg" || exit 1
echo "$FIGURES/divergence.svg"
