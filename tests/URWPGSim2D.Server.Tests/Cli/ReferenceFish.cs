namespace URWPGSim2D.Server.Tests.Cli;

/// <summary>
/// The fish's eight leaf polygons computed straight from the reference's formulas
/// (shared/reference/urwpgsim2d.md, "Fish model") in double precision, as independent truth
/// for the CLI's output; and a polygon comparison that ignores the start vertex and the winding.
/// </summary>
internal static class ReferenceFish
{
    /// <summary>Leaf names in FishPart order, as the CLI writes them.</summary>
    public static readonly string[] PartNames = ["leftPectoral", "body", "rightPectoral", "tail1", "tail2", "tail3", "leftCaudal", "rightCaudal"];

    /// <summary>The deployed size: L, W, H, L1, L2, L3.</summary>
    public static readonly double[] DeployedSize = [160, 45, 30, 88, 66, 55];

    /// <summary>The leaves (world x, z) of a fish at position (x, z), heading θ, joints φ1..φ3.</summary>
    public static (double X, double Z)[][] Leaves(double[] size, double x, double z, double heading, double j1, double j2, double j3)
    {
        double l = size[0], w = size[1], h = size[2];
        double[] lengths = [size[3], size[4], size[5]];
        double[] start = [0.266112, 0.231336, 0.115668];
        double[] end = [0.2193408, 0.14994, 0.089964];
        double[] joints = [j1, j2, j3];

        // Body frame: local (a, b) → P + a·u − b·n, u = (cos θ, sin θ), n = (sin θ, −cos θ).
        (double X, double Z) Body(double a, double b) =>
            (x + (a * Math.Cos(heading)) - (b * Math.Sin(heading)), z + (a * Math.Sin(heading)) + (b * Math.Cos(heading)));

        var leaves = new (double X, double Z)[8][];
        var fin = new (double A, double B)[] { (-7 * l / 24, (-w / 2) - 37.5), (-7 * l / 24, (-w / 2) - 25), (-l / 12, -w / 2), (l / 4, -w / 2) };
        leaves[0] = Array.ConvertAll(fin, p => Body(p.A, p.B));
        leaves[1] = [Body(l / 2, -w / 2), Body((l / 2) + h, 0), Body(l / 2, w / 2), Body(-l / 2, w / 2), Body(-l / 2, -w / 2)];
        leaves[2] = Array.ConvertAll(fin, p => Body(p.A, -p.B));

        var s = Body(-l / 2, 0);
        (double X, double Z) d3 = default, n3 = default, e2 = default, e3 = default;
        for (int i = 0; i < 3; i++)
        {
            double angle = heading + joints[i];
            (double X, double Z) d = (Math.Cos(angle), Math.Sin(angle));
            (double X, double Z) n = (Math.Sin(angle), -Math.Cos(angle));
            var e = (X: s.X - (lengths[i] * d.X), Z: s.Z - (lengths[i] * d.Z));
            double hs = start[i] * lengths[i], he = end[i] * lengths[i];
            leaves[3 + i] =
            [
                (s.X + (hs * n.X), s.Z + (hs * n.Z)), (s.X - (hs * n.X), s.Z - (hs * n.Z)),
                (e.X - (he * n.X), e.Z - (he * n.Z)), (e.X + (he * n.X), e.Z + (he * n.Z)),
            ];
            if (i == 1)
            {
                e2 = e;
            }

            if (i == 2)
            {
                (d3, n3, e3) = (d, n, e);
            }

            s = e;
        }

        // Caudal fin: A_k = E2 − k·L3·d3; tips and notch offset along n3.
        double l3 = lengths[2], he3 = end[2] * l3;
        (double X, double Z) At(double k, double along) => (e2.X - (k * l3 * d3.X) + (along * n3.X), e2.Z - (k * l3 * d3.Z) + (along * n3.Z));
        var notch = At(1.8, 10);
        leaves[6] = [At(2.0, 50), notch, (e3.X - (he3 * n3.X), e3.Z - (he3 * n3.Z))];
        leaves[7] = [At(1.8, -35), notch, (e3.X + (he3 * n3.X), e3.Z + (he3 * n3.Z))];
        return leaves;
    }

    /// <summary>Asserts that two polygons have the same vertices in the same cyclic order, in either direction, within <paramref name="tolerance"/>.</summary>
    public static void AssertSamePolygon(IReadOnlyList<(double X, double Z)> expected, IReadOnlyList<(double X, double Z)> actual, double tolerance, string what)
    {
        Assert.True(expected.Count == actual.Count, $"{what}: {actual.Count} vertices, expected {expected.Count}");
        int n = expected.Count;
        for (int shift = 0; shift < n; shift++)
        {
            foreach (int direction in new[] { 1, -1 })
            {
                bool all = true;
                for (int i = 0; i < n && all; i++)
                {
                    var e = expected[i];
                    var a = actual[(((shift + (direction * i)) % n) + n) % n];
                    all = Math.Abs(e.X - a.X) <= tolerance && Math.Abs(e.Z - a.Z) <= tolerance;
                }

                if (all)
                {
                    return;
                }
            }
        }

        Assert.Fail($"{what}: vertices [{Text(actual)}] are not the polygon [{Text(expected)}] (tolerance {tolerance})");
    }

    private static string Text(IReadOnlyList<(double X, double Z)> points)
    {
        var parts = new List<string>();
        foreach (var p in points)
        {
            parts.Add(FormattableString.Invariant($"({p.X:0.####}, {p.Z:0.####})"));
        }

        return string.Join(", ", parts);
    }
}
