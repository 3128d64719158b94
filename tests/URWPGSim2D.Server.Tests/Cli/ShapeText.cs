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

    /// <summary>A fish SHAPE (deployed size unless <paramref name="size"/> is given as {length, width, head, L1, L2, L3}).</summary>
    public static string Fish(double x, double z, double heading, double j1 = 0, double j2 = 0, double j3 = 0, double[]? size = null)
    {
        string text = $$"""{"type":"fish","position":[{{Num(x)}},{{Num(z)}}],"heading":{{Num(heading)}},"joints":[{{Num(j1)}},{{Num(j2)}},{{Num(j3)}}]""";
        if (size is not null)
        {
            text += $$""","size":{"length":{{Num(size[0])}},"width":{{Num(size[1])}},"head":{{Num(size[2])}},"joints":[{{Num(size[3])}},{{Num(size[4])}},{{Num(size[5])}}]}""";
        }

        return text + "}";
    }

    /// <summary>A JSON array of SHAPE objects.</summary>
    public static string Shapes(params string[] shapes) => "[" + string.Join(",", shapes) + "]";

    public static string Pair(string a, string b) => $$"""{"a":{{a}},"b":{{b}}}""";

    public static string Pairs(params string[] pairs) => "[" + string.Join(",", pairs) + "]";
}
