using URWPGSim2D.Common;
using URWPGSim2D.Core;
using Xna = Microsoft.Xna.Framework;

namespace URWPGSim2D.StrategyHelper;

/// <summary>
/// The original's strategy helpers, re-implemented from their documented behaviour: swim to a point
/// and push through it (<see cref="Dribble"/>), settle into a pose (<see cref="PoseToPose"/>) and the
/// field direction of a vector (<see cref="GetAngleDegree"/>). They read the gear tables of
/// <see cref="DataBasedOnExperiment"/>. A team that ships its own <c>StrategyHelper.cs</c> uses its own copy instead.
/// </summary>
public static class Helpers
{
    /// <summary>
    /// Picks gears that take <paramref name="fish"/> to <paramref name="destPtMm"/> (used to push a ball
    /// toward a goal): the aim is the direction from the fish's centre to the point (or
    /// <paramref name="destDirRad"/> once within 30 mm). Off by more than <paramref name="angleTheta2"/>°
    /// the fish turns on the spot (VCode 1); within <paramref name="angleTheta1"/>° it swims at
    /// <paramref name="VCode1"/> beyond <paramref name="disThreshold"/> mm and <paramref name="VCode2"/> inside
    /// it; in between it takes the slowest VCode (≤ 10) that covers the distance in the time the turn takes.
    /// The TCode is the gentlest that turns through the error within min(distance / top speed, 15 cycles);
    /// when the current turn rate would overshoot the error within <paramref name="cycles"/> cycles, the
    /// fish counter-steers (TCode 12 when turning left, 2 when turning right).
    /// </summary>
    /// <param name="decision">Receives the gears.</param>
    /// <param name="fish">The fish.</param>
    /// <param name="destPtMm">Target point, mm.</param>
    /// <param name="destDirRad">Direction wanted at the target, rad.</param>
    /// <param name="angleTheta1">Error below which the fish swims fast, degrees.</param>
    /// <param name="angleTheta2">Error above which the fish turns slowly, degrees.</param>
    /// <param name="disThreshold">Distance separating <paramref name="VCode1"/> from <paramref name="VCode2"/>, mm.</param>
    /// <param name="VCode1">Speed gear when far and aligned.</param>
    /// <param name="VCode2">Speed gear when near and aligned.</param>
    /// <param name="cycles">Look-ahead against overshooting the turn, cycles (5..20 suggested).</param>
    /// <param name="msPerCycle">Cycle length, ms (100).</param>
    /// <param name="flag">Measure the distance from the centre (true) or from the head tip, <c>PolygonVertices[0]</c> (false).</param>
    public static void Dribble(ref Decision decision, RoboFish fish, Xna.Vector3 destPtMm, float destDirRad,
        float angleTheta1, float angleTheta2, float disThreshold, int VCode1, int VCode2, int cycles, int msPerCycle, bool flag)
    {
        ArgumentNullException.ThrowIfNull(fish);
        float[] speeds = DataBasedOnExperiment.VCodeAndVelocityTable;
        float[] turns = DataBasedOnExperiment.TCodeAndAngularVelocityTable;
        Xna.Vector3 from = flag ? fish.PositionMm : fish.PolygonVertices[0];
        double distance = PlaneDistance(from, destPtMm);
        double aim = distance < 30.0 ? destDirRad : Xna.MathHelper.ToRadians(GetAngleDegree(destPtMm - fish.PositionMm));
        double error = OneTurnWrap(aim - fish.BodyDirectionRad);

        // Speed: the slowest gear (≤ 10) that covers the distance while turning through the error at full rate.
        double fullTurnRate = (Math.Abs(turns[0]) + Math.Abs(turns[14])) / 2.0;
        double neededSpeed = distance / Math.Abs(error / fullTurnRate);
        int vcode = 1;
        while (vcode < 10 && speeds[vcode] < neededSpeed)
        {
            vcode++;
        }

        if (Math.Abs(error) > angleTheta2 * Math.PI / 180.0)
        {
            vcode = 1;
        }
        else if (Math.Abs(error) < angleTheta1 * Math.PI / 180.0)
        {
            vcode = distance > disThreshold ? VCode1 : VCode2;
        }

        // Turn: the gentlest gear reaching the turn rate that closes the error in the time to arrive.
        double horizon = Math.Min(distance / speeds[14], 15 * msPerCycle / 1000.0);
        double neededRate = error / horizon;
        double lookAhead = cycles * msPerCycle / 1000.0;
        int tcode = 7;
        if (error <= 0)
        {
            while (tcode > 0 && turns[tcode] > neededRate)
            {
                tcode--;
            }

            if (fish.AngularVelocityRadPs * lookAhead < error)
            {
                tcode = 12;
            }
        }
        else
        {
            while (tcode < 14 && turns[tcode] < neededRate)
            {
                tcode++;
            }

            if (fish.AngularVelocityRadPs * lookAhead > error)
            {
                tcode = 2;
            }
        }

        decision.VCode = vcode;
        decision.TCode = tcode;
    }

    /// <summary>
    /// Picks gears that bring <paramref name="fish"/> to the pose (<paramref name="destPtMm"/>,
    /// <paramref name="destDirRad"/>). Far away (more than 20 % of <paramref name="disThreshold"/> from the
    /// staging point <paramref name="disThreshold"/> mm behind the target, and <paramref name="times"/> = 0) it
    /// swims at VCode 8 toward the staging point, steering with the line-of-sight rate; near, it counts
    /// <paramref name="times"/> up and follows a smooth pose-stabilising law in the target's frame, stopping
    /// (V0 T7) within 150 mm and 10° of aim. An aim error beyond <paramref name="angThreshold"/>° always
    /// turns on the spot (VCode 1, TCode 1 left or 13 right).
    /// </summary>
    /// <param name="decision">Receives the gears.</param>
    /// <param name="fish">The fish.</param>
    /// <param name="destPtMm">Target position, mm.</param>
    /// <param name="destDirRad">Target direction, rad.</param>
    /// <param name="angThreshold">Aim error above which the fish turns on the spot, degrees (30 suggested).</param>
    /// <param name="disThreshold">Distance of the staging point behind the target, mm.</param>
    /// <param name="msPerCycle">Cycle length, ms (100).</param>
    /// <param name="times">Cycles spent in the near phase; keep it between calls (start at 0).</param>
    public static void PoseToPose(ref Decision decision, RoboFish fish, Xna.Vector3 destPtMm, float destDirRad,
        float angThreshold, float disThreshold, int msPerCycle, ref int times)
    {
        ArgumentNullException.ThrowIfNull(fish);
        float[] speeds = DataBasedOnExperiment.VCodeAndVelocityTable;
        float[] turns = DataBasedOnExperiment.TCodeAndAngularVelocityTable;
        Xna.Vector3 from = fish.PositionMm;
        double distanceToTarget = PlaneDistance(from, destPtMm);
        var staging = new Xna.Vector3(
            (float)(destPtMm.X - (disThreshold * Math.Cos(destDirRad))), 0f, (float)(destPtMm.Z - (disThreshold * Math.Sin(destDirRad))));
        bool far = PlaneDistance(from, staging) > 0.2 * disThreshold && times == 0;
        Xna.Vector3 goal = far ? staging : destPtMm;
        double error = OneTurnWrap(Xna.MathHelper.ToRadians(GetAngleDegree(goal - fish.PositionMm)) - fish.BodyDirectionRad);

        if (Math.Abs(error) > angThreshold * Math.PI / 180.0)
        {
            decision.VCode = 1;
            decision.TCode = error <= 0 ? 1 : 13;
            return;
        }

        if (far)
        {
            times = 0;
            float dx = goal.X - from.X, dz = goal.Z - from.Z;
            float vx = fish.VelocityMmPs * MathF.Cos(fish.BodyDirectionRad);
            float vz = fish.VelocityMmPs * MathF.Sin(fish.BodyDirectionRad);
            // The original's steering term (its sign convention kept: Z is measured upward in it).
            float lineOfSightRate = ((dx * vz) + (dz * vx)) / ((dx * dx) + (dz * dz));
            decision.VCode = 8;
            decision.TCode = TurnGear(turns, error, 50.0 * lineOfSightRate);
            return;
        }

        times++;
        const float K1 = 0.6f, K2 = 12f, K3 = 18f;
        float headingError = destDirRad - fish.BodyDirectionRad;
        var local = default(Xna.Vector3);
        UrwpgSimHelper.CoordinateTransformation(destDirRad, destPtMm, ref local, from);
        float ramp = (float)Math.Pow(Math.Sin(times * msPerCycle / 1000f), 2.0);
        float u1 = -K1 * local.X * ramp;
        float u2 = (u1 * K2 * local.Z) + (u1 * K3 * MathF.Tan(headingError));
        double wantedSpeed = u1 / Math.Cos(headingError);
        double wantedRate = u2 * Math.Pow(Math.Cos(headingError), 2.0);
        if (distanceToTarget < 150.0 && Math.Abs(error) < 10.0 * Math.PI / 180.0)
        {
            decision.VCode = 0;
            decision.TCode = 7;
            return;
        }

        int vcode = 2;
        while (vcode < 14 && speeds[vcode] < wantedSpeed)
        {
            vcode++;
        }

        decision.VCode = vcode;
        decision.TCode = TurnGear(turns, error, wantedRate);
    }

    /// <summary>
    /// The field direction of a vector's (X, Z) part in degrees, in (−180, 180], from +X toward +Z
    /// (clockwise on screen); 0 for a zero vector, ±90 when X is within float epsilon of 0.
    /// </summary>
    /// <param name="v">The vector (Y is ignored).</param>
    /// <returns>Direction, degrees.</returns>
    public static float GetAngleDegree(Xna.Vector3 v)
    {
        float x = v.X, z = v.Z;
        if (Math.Abs(x) < float.Epsilon)
        {
            return z > 0 ? 90f : z < 0 ? -90f : 0f;
        }

        float degrees = (float)(180.0 * Math.Atan(z / x) / Math.PI);
        if (x > 0)
        {
            return degrees;
        }

        return z >= 0 ? degrees + 180f : degrees - 180f;
    }

    // Turn gear from straight (7) toward the error's side until its rate reaches the wanted rate (0..14).
    private static int TurnGear(float[] turns, double error, double wantedRate)
    {
        int tcode = 7;
        if (error <= 0)
        {
            while (tcode > 0 && turns[tcode] > wantedRate)
            {
                tcode--;
            }
        }
        else
        {
            while (tcode < 14 && turns[tcode] < wantedRate)
            {
                tcode++;
            }
        }

        return tcode;
    }

    private static double PlaneDistance(Xna.Vector3 a, Xna.Vector3 b) =>
        Math.Sqrt(((b.X - a.X) * (double)(b.X - a.X)) + ((b.Z - a.Z) * (double)(b.Z - a.Z)));

    // One step of wrapping, as the original does: differences of two angles in (−π, π] land in (−π, π].
    private static double OneTurnWrap(double angle) =>
        angle > Math.PI ? angle - (2 * Math.PI) : angle < -Math.PI ? angle + (2 * Math.PI) : angle;
}
