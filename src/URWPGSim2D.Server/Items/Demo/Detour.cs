using System;
using System.Numerics;

namespace URWPGSim2D.Server.Items.Demo;

/// <summary>
/// The way round obstacles: when the straight line to a point crosses an obstacle (its bounding
/// box grown by a margin), head for the corner of that box, a little farther out, that makes the
/// shortest way and can itself be reached straight; otherwise head for the point. Pure functions
/// of the snapshot's obstacles; nothing is allocated.
/// </summary>
internal static class Detour
{
    private const float CornerOut = 40f;

    /// <summary>Where to head now on the way from <paramref name="from"/> to <paramref name="to"/>.</summary>
    /// <param name="obstacles">The snapshot's obstacles.</param>
    /// <param name="from">The fish's position.</param>
    /// <param name="to">Where it wants to go.</param>
    /// <param name="margin">Clearance kept from every obstacle's bounding box, mm.</param>
    public static Vector2 Aim(ReadOnlySpan<ObstacleView> obstacles, Vector2 from, Vector2 to, float margin)
    {
        int blocking = FirstBlocking(obstacles, from, to, margin);
        if (blocking < 0)
        {
            return to;
        }

        Vector2 half = HalfExtent(obstacles[blocking]) + new Vector2(margin + CornerOut);
        Vector2 centre = obstacles[blocking].Center;
        Vector2 best = to;
        float bestCost = float.PositiveInfinity;
        bool bestFree = false;
        for (int k = 0; k < 4; k++)
        {
            Vector2 corner = centre + new Vector2((k & 1) == 0 ? -half.X : half.X, (k & 2) == 0 ? -half.Y : half.Y);
            bool free = FirstBlocking(obstacles, from, corner, margin) < 0;
            float cost = Vector2.Distance(from, corner) + Vector2.Distance(corner, to);
            if ((free && !bestFree) || (free == bestFree && cost < bestCost))
            {
                best = corner;
                bestCost = cost;
                bestFree = free;
            }
        }

        return best;
    }

    /// <summary>The first obstacle whose grown bounding box the segment crosses, or −1.</summary>
    public static int FirstBlocking(ReadOnlySpan<ObstacleView> obstacles, Vector2 from, Vector2 to, float margin)
    {
        for (int i = 0; i < obstacles.Length; i++)
        {
            Vector2 half = HalfExtent(obstacles[i]) + new Vector2(margin);
            if (Crosses(from - obstacles[i].Center, to - obstacles[i].Center, half))
            {
                return i;
            }
        }

        return -1;
    }

    // Half the axis-aligned bounding box of an obstacle.
    private static Vector2 HalfExtent(in ObstacleView o)
    {
        if (o.Kind == ObstacleKind.Round)
        {
            return new Vector2(o.Radius);
        }

        float c = MathF.Abs(MathF.Cos(o.Heading)), s = MathF.Abs(MathF.Sin(o.Heading));
        return new Vector2((o.Length * c) + (o.Width * s), (o.Length * s) + (o.Width * c)) * 0.5f;
    }

    // Whether the segment a–b meets the box [−half, half] (slab test).
    private static bool Crosses(Vector2 a, Vector2 b, Vector2 half)
    {
        Vector2 d = b - a;
        float t0 = 0f, t1 = 1f;
        for (int axis = 0; axis < 2; axis++)
        {
            float p = axis == 0 ? a.X : a.Y, v = axis == 0 ? d.X : d.Y, h = axis == 0 ? half.X : half.Y;
            if (MathF.Abs(v) < 1e-6f)
            {
                if (p < -h || p > h)
                {
                    return false;
                }

                continue;
            }

            float u0 = (-h - p) / v, u1 = (h - p) / v;
            if (u0 > u1)
            {
                (u0, u1) = (u1, u0);
            }

            t0 = MathF.Max(t0, u0);
            t1 = MathF.Min(t1, u1);
            if (t0 > t1)
            {
                return false;
            }
        }

        return true;
    }
}
