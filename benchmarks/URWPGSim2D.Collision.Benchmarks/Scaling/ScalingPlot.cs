using System.Globalization;
using System.Linq;
using System.Text;

namespace URWPGSim2D.Collision.Benchmarks.Scaling;

/// <summary>
/// Writes the cost-per-cycle plot of docs/performance.md: time per cycle (log scale) against the
/// number of objects (log scale), one line per measured series, with a dashed slope-1 guide
/// (cost proportional to the count). Plain SVG, nothing but numbers in it.
/// </summary>
public static class ScalingPlot
{
    private const double Width = 820, Height = 460, Left = 80, Right = 300, Top = 40, Bottom = 60;

    private static readonly string[] Colours = ["#c0392b", "#2471a3", "#1e8449", "#b7950b", "#7d3c98", "#616a6b"];

    /// <summary>One measured line: a name and (objects, nanoseconds per cycle) points.</summary>
    /// <param name="Name">Legend text.</param>
    /// <param name="Points">Object count and median time per cycle, ns.</param>
    public sealed record Series(string Name, IReadOnlyList<(double Objects, double Nanoseconds)> Points);

    /// <summary>Writes the plot to <paramref name="path"/>.</summary>
    /// <param name="path">Output SVG file.</param>
    /// <param name="title">Title line.</param>
    /// <param name="series">The lines to draw (at least one point in all).</param>
    public static void Write(string path, string title, IReadOnlyList<Series> series)
    {
        var points = series.SelectMany(s => s.Points).ToArray();
        if (points.Length == 0)
        {
            throw new ArgumentException("no points to plot", nameof(series));
        }

        double xMin = Math.Pow(10, Math.Floor(Math.Log10(points.Min(p => p.Objects))));
        double xMax = Math.Pow(10, Math.Ceiling(Math.Log10(points.Max(p => p.Objects))));
        double yMin = Math.Pow(10, Math.Floor(Math.Log10(Math.Min(points.Min(p => p.Nanoseconds), 8e5))));
        double yMax = Math.Pow(10, Math.Ceiling(Math.Log10(Math.Max(points.Max(p => p.Nanoseconds), 1e7))));
        double X(double v) => Left + ((Math.Log10(v) - Math.Log10(xMin)) / (Math.Log10(xMax) - Math.Log10(xMin)) * (Width - Left - Right));
        double Y(double v) => Height - Bottom - ((Math.Log10(v) - Math.Log10(yMin)) / (Math.Log10(yMax) - Math.Log10(yMin)) * (Height - Top - Bottom));

        var s = new StringBuilder();
        s.Append(F($"<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{Width}\" height=\"{Height}\" viewBox=\"0 0 {Width} {Height}\" font-family=\"sans-serif\" font-size=\"12\">\n"));
        s.Append(F($"<rect width=\"{Width}\" height=\"{Height}\" fill=\"white\"/>\n"));
        s.Append(F($"<text x=\"{Left}\" y=\"22\" font-size=\"14\">{Escape(title)}</text>\n"));
        for (double x = xMin; x <= xMax * 1.0001; x *= 10)
        {
            s.Append(F($"<line x1=\"{X(x):0.#}\" y1=\"{Top}\" x2=\"{X(x):0.#}\" y2=\"{Height - Bottom}\" stroke=\"#ddd\"/>\n"));
            s.Append(F($"<text x=\"{X(x):0.#}\" y=\"{Height - Bottom + 18}\" text-anchor=\"middle\">{x:#,0}</text>\n"));
        }

        for (double y = yMin; y <= yMax * 1.0001; y *= 10)
        {
            s.Append(F($"<line x1=\"{Left}\" y1=\"{Y(y):0.#}\" x2=\"{Width - Right}\" y2=\"{Y(y):0.#}\" stroke=\"#ddd\"/>\n"));
            s.Append(F($"<text x=\"{Left - 6}\" y=\"{Y(y) + 4:0.#}\" text-anchor=\"end\">{Time(y)}</text>\n"));
        }

        s.Append(F($"<text x=\"{(Left + Width - Right) / 2:0.#}\" y=\"{Height - 18}\" text-anchor=\"middle\">fish and balls (same density, the pool grows with the count)</text>\n"));
        s.Append(F($"<text x=\"18\" y=\"{(Top + Height - Bottom) / 2:0.#}\" text-anchor=\"middle\" transform=\"rotate(-90 18 {(Top + Height - Bottom) / 2:0.#})\">time per cycle</text>\n"));

        // A slope-1 guide through the first series' smallest point.
        var anchor = series[0].Points.OrderBy(p => p.Objects).First(); // the first series sets the slope-1 guide
        double guideEnd = Math.Min(xMax, anchor.Objects * (yMax / anchor.Nanoseconds));
        s.Append(F($"<line x1=\"{X(anchor.Objects):0.#}\" y1=\"{Y(anchor.Nanoseconds):0.#}\" x2=\"{X(guideEnd):0.#}\" y2=\"{Y(anchor.Nanoseconds * guideEnd / anchor.Objects):0.#}\" stroke=\"#aaa\" stroke-dasharray=\"6 4\"/>\n"));

        for (int i = 0; i < series.Count; i++)
        {
            string colour = Colours[i % Colours.Length];
            var line = series[i].Points.OrderBy(p => p.Objects).ToArray();
            s.Append("<polyline fill=\"none\" stroke=\"").Append(colour).Append("\" stroke-width=\"2\" points=\"");
            s.Append(string.Join(" ", line.Select(p => F($"{X(p.Objects):0.#},{Y(p.Nanoseconds):0.#}")))).Append("\"/>\n");
            foreach (var p in line)
            {
                s.Append(F($"<circle cx=\"{X(p.Objects):0.#}\" cy=\"{Y(p.Nanoseconds):0.#}\" r=\"3.5\" fill=\"{colour}\"/>\n"));
            }

            double ly = Top + 10 + (i * 20);
            s.Append(F($"<line x1=\"{Width - Right + 12}\" y1=\"{ly:0.#}\" x2=\"{Width - Right + 36}\" y2=\"{ly:0.#}\" stroke=\"{colour}\" stroke-width=\"2\"/>\n"));
            s.Append(F($"<text x=\"{Width - Right + 42}\" y=\"{ly + 4:0.#}\">{Escape(series[i].Name)}</text>\n"));
        }

        double gy = Top + 10 + (series.Count * 20);
        s.Append(F($"<line x1=\"{Width - Right + 12}\" y1=\"{gy:0.#}\" x2=\"{Width - Right + 36}\" y2=\"{gy:0.#}\" stroke=\"#aaa\" stroke-dasharray=\"6 4\"/>\n"));
        s.Append(F($"<text x=\"{Width - Right + 42}\" y=\"{gy + 4:0.#}\">∝ objects (slope 1)</text>\n"));
        s.Append("</svg>\n");
        File.WriteAllText(path, s.ToString(), new UTF8Encoding(false));
    }

    private static string Time(double ns) => ns switch
    {
        >= 1e9 => F($"{ns / 1e9:0.###} s"),
        >= 1e6 => F($"{ns / 1e6:0.###} ms"),
        >= 1e3 => F($"{ns / 1e3:0.###} µs"),
        _ => F($"{ns:0.###} ns"),
    };

    private static string Escape(string text) => text.Replace("&", "&amp;", StringComparison.Ordinal).Replace("<", "&lt;", StringComparison.Ordinal);

    private static string F(FormattableString text) => text.ToString(CultureInfo.InvariantCulture);
}
