using System.Numerics;
using URWPGSim2D.Collision.Fish;
using URWPGSim2D.Common;
using URWPGSim2D.Strategies;
using Xna = Microsoft.Xna.Framework;

namespace URWPGSim2D.Compat.Adapter;

/// <summary>
/// Builds the original's <see cref="Mission"/> from a <see cref="MatchSnapshot"/>: a fresh deep copy
/// for one team every call, in absolute field coordinates, with the left team first in
/// <see cref="Mission.TeamsRef"/>. What the original leaves out of a strategy's copy (<c>Pre*</c> values,
/// the decisions being executed, obstacle corners) stays at its default.
/// </summary>
internal sealed class MissionBuilder
{
    private readonly Dictionary<int, FishModel> _models = new();

    /// <summary>Name given to each team in <see cref="TeamCommonPara.Name"/> (index = server team).</summary>
    public string[] TeamNames { get; } = ["team 0", "team 1"];

    /// <summary>Builds this cycle's mission.</summary>
    /// <param name="snapshot">The world as strategies see it.</param>
    public Mission Build(MatchSnapshot snapshot)
    {
        ArgumentNullException.ThrowIfNull(snapshot);
        var mission = new Mission { Source = snapshot };
        int teamCount = TeamCount(snapshot);
        var perTeam = new int[teamCount];
        foreach (ref readonly var f in snapshot.Fish)
        {
            perTeam[f.Team]++;
        }

        int fishPerTeam = 0;
        foreach (int n in perTeam)
        {
            fishPerTeam = Math.Max(fishPerTeam, n);
        }

        var para = mission.CommonPara;
        para.Name = snapshot.ItemName;
        para.TeamCount = teamCount;
        para.FishCntPerTeam = fishPerTeam;
        para.MsPerCycle = 100;
        int total = snapshot.TotalCycles > 0 ? snapshot.TotalCycles : 6000;
        para.TotalSeconds = total / 10;
        para.RemainingCycles = Math.Max(0, total - snapshot.Cycle);
        para.IsRunning = true;
        para.IsExchangedHalfCourt = snapshot.SidesSwapped;
        para.IsGoalBlockNeeded = true;
        para.IsFieldInnerLinesNeeded = 1;

        for (int index = 0; index < teamCount; index++)
        {
            int team = ServerTeam(snapshot, index, teamCount);
            var t = new Team<RoboFish>();
            t.Para.FishCount = perTeam[team];
            t.Para.MyHalfCourt = index % 2 == 0 ? HalfCourt.LEFT : HalfCourt.RIGHT; // four teams: 0 and 2 left, 1 and 3 right, as Match4Teams
            t.Para.Score = snapshot.GoalsOf(team);
            t.Para.Name = team < TeamNames.Length ? TeamNames[team] : $"team {team}";
            t.Para.IsReady = true;
            foreach (ref readonly var f in snapshot.Fish)
            {
                if (f.Team == team)
                {
                    t.Fishes.Add(Fish(f));
                }
            }

            mission.TeamsRef.Add(t);
        }

        var env = mission.EnvRef;
        Field.Instance().SetSize((int)MathF.Round(snapshot.FieldLength), (int)MathF.Round(snapshot.FieldWidth));
        env.FieldInfo = Field.Instance();
        foreach (ref readonly var b in snapshot.Balls)
        {
            float speed = b.Velocity.Length();
            env.Balls.Add(new Ball((int)MathF.Round(b.Radius))
            {
                PositionMm = Xna.Vector3.FromXZ(b.Position),
                VelocityMmPs = speed,
                VelocityDirectionRad = speed > 0f ? MathF.Atan2(b.Velocity.Y, b.Velocity.X) : 0f,
            });
        }

        foreach (ref readonly var o in snapshot.Obstacles)
        {
            string name = $"obstacle{o.Index}";
            if (o.Kind == ObstacleKind.Round)
            {
                env.ObstaclesRound.Add(new RoundedObstacle { Name = name, PositionMm = Xna.Vector3.FromXZ(o.Center), RadiusMm = (int)MathF.Round(o.Radius) });
            }
            else
            {
                env.ObstaclesRect.Add(new RectangularObstacle
                {
                    Name = name, PositionMm = Xna.Vector3.FromXZ(o.Center), DirectionRad = o.Heading,
                    LengthMm = (int)MathF.Round(o.Length), WidthMm = (int)MathF.Round(o.Width),
                });
            }
        }

        foreach (var pair in snapshot.Variables)
        {
            mission.HtMissionVariables[pair.Key] = pair.Value;
        }

        return mission;
    }

    /// <summary>Index in <see cref="Mission.TeamsRef"/> of a server team (the left team is index 0).</summary>
    /// <param name="snapshot">The snapshot.</param>
    /// <param name="team">Server team (0 attacks +X before the swap).</param>
    public static int MissionTeam(MatchSnapshot snapshot, int team) =>
        TeamCount(snapshot) == 2 && snapshot.SidesSwapped ? 1 - team : team;

    private static int ServerTeam(MatchSnapshot snapshot, int index, int teamCount) =>
        teamCount == 2 && snapshot.SidesSwapped ? 1 - index : index;

    private static int TeamCount(MatchSnapshot snapshot)
    {
        int teams = 1;
        foreach (ref readonly var f in snapshot.Fish)
        {
            teams = Math.Max(teams, f.Team + 1);
        }

        return teams;
    }

    private RoboFish Fish(in FishView f)
    {
        var fish = new RoboFish
        {
            BodyLength = (int)MathF.Round(f.BodyLength),
            BodyWidth = (int)MathF.Round(f.Width),
            HeadLength = (int)MathF.Round(f.HeadLength),
            TailJointLength1 = (int)MathF.Round(f.TailLength1),
            TailJointLength2 = (int)MathF.Round(f.TailLength2),
            TailJointLength3 = (int)MathF.Round(f.TailLength3),
            PositionMm = Xna.Vector3.FromXZ(f.Position),
            BodyDirectionRad = Xna.MathHelper.WrapAngle(f.Heading),
            VelocityMmPs = f.Speed,
            AngularVelocityRadPs = f.AngularSpeed,
            TailToBodyAngle1 = f.Joint1,
            TailToBodyAngle2 = f.Joint2,
            TailToBodyAngle3 = f.Joint3,
        };
        fish.VelocityDirectionRad = fish.BodyDirectionRad;
        fish.UpdateRadii();

        var size = new FishSize(f.BodyLength, f.Width, f.HeadLength, f.TailLength1, f.TailLength2, f.TailLength3);
        var pose = new FishPose(f.Position, f.Heading, f.Joint1, f.Joint2, f.Joint3);
        if (!_models.TryGetValue(f.Index, out var model) || model.Size != size)
        {
            model = new FishModel(size, pose);
            _models[f.Index] = model;
        }
        else
        {
            model.SetPose(pose);
        }

        fish.Outline(f.Position, f.Heading, f.BodyLength, f.Width, f.HeadLength, model);
        return fish;
    }
}
