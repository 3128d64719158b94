using System.Globalization;

namespace URWPGSim2D.Server.Tests.Cli;

/// <summary>SHAPE objects and pair arrays as JSON text, for building inputs.</summary>
internal static class ShapeText
{
    public static string Num(double value) => value.ToString("R", CultureInfo.InvariantCulture);

    public static string Circle(double x, double z, double r) =>
        $$"""{"type":"circle","center":[{{Num(x)}},{{Num(z)}}],"radius":{{Num(r)}}}""";

    public static string Aabb(double minX, double minZ, double maxX, double maxZ) =>
        $$"""{"type":"aabb","min":[{{Num(minX)}},{{Num(minZ)}}],"max":[{{Num(maxX)}},{{Num(maxZ)}}]}""";

    public static string KDop8(double[] min, double[] max) =>
        $$"""{"type":"kdop8","min":[{{string.Join(",", System.Array.ConvertAll(min, Num))}}],"max":[{{string.Join(",", System.Array.ConvertAll(max, Num))}}]}""";

    /// <summary>The 8-DOP of the square with corners at centre ± (h, 0) and centre ± (0, h) (a "diamond").</summary>
    public static string Diamond(double cx, double cz, double h)
    {
        double s = System.Math.Sqrt(0.5);
        double d2 = (cx + cz) * s, d3 = (cx - cz) * s, hd = h * s;
        return KDop8([cx - h, cz - h, d2 - hd, d3 - hd], [cx + h, cz + h, d2 + hd, d3 + hd]);
    }

    public static string Polygon(params (double X, double Z)[] vertices) =>
        $$"""{"type":"polygon","vertices":[{{string.Join(",", System.Array.ConvertAll(vertices, v => $"[{Num(v.X)},{Num(v.Z)}]"))}}]}""";

    public static string Segment(double ax, double az, double bx, double bz) =>
        $$"""{"type":"segment","a":[{{Num(ax)}},{{Num(az)}}],"b":[{{Num(bx)}},{{Num(bz)}}]}""";

    public static string Pair(string a, string b) => $$"""{"a":{{a}},"b":{{b}}}""";

    public static string Pairs(params string[] pairs) => "[" + string.Join(",", pairs) + "]";
}
