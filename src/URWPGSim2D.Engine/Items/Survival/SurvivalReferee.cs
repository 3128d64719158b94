using System.Globalization;
using URWPGSim2D.Strategies;

namespace URWPGSim2D.Engine.Items.Survival;

/// <summary>
/// The rules of 生存挑战, as the original's <c>MatchTransfer</c>. Team 0 hunts in the first half,
/// team 1 in the second. The hunting team plays with its fish 0 only (fish 1–3 parked off the
/// field); the hunted team's fish 1–3 are the prey, its fish 0 plays free but cannot be caught.
/// After the strategies decide, fish 1–3 of either team are held to speed gear 8 at most. After
/// every cycle a contact between the hunter and a prey fish not yet caught is a catch: +1 for the
/// hunting team (event <c>catch</c>), and the prey fish j is parked off the field at
/// (2415 − 300 j, 1591). A half ends at three catches or when its time is up; at half time every
/// fish takes the start pose of its team's new role. Equal scores: the team whose last catch came
/// earlier, counted from the start of its half, wins (no catches on either side: a tie).
/// <c>HtMissionVariables</c>: <c>IsYellowFish{2,3,4}Caught</c> (team 1's fish 1–3 caught, the
/// original's yellow fish) and <c>IsRedFish{2,3,4}Caught</c> (team 0's), 0 or 1.
/// </summary>
internal sealed class SurvivalReferee : ItemReferee
{
    private const int Never = int.MaxValue;

    private static readonly string[][] Keys =
    [
        ["IsRedFish2Caught", "IsRedFish3Caught", "IsRedFish4Caught"],
        ["IsYellowFish2Caught", "IsYellowFish3Caught", "IsYellowFish4Caught"],
    ];

    // [team, j − 1]: whether fish j of that team has been caught.
    private readonly bool[,] _caught = new bool[2, SurvivalLayout.FishPerTeam - 1];

    // Per team: the cycle of its last catch, counted from the start of its half.
    private readonly int[] _lastCatch = [Never, Never];

    private int[] _rank = [];

    /// <summary>Creates the referee of one match.</summary>
    public SurvivalReferee(SurvivalItem item, ScenarioDefinition scenario, int cycles)
        : base(item, scenario, cycles, halves: 2)
    {
    }

    /// <summary>The team hunting in the current half (0 first, then 1).</summary>
    public int Hunter => SidesSwapped ? 1 : 0;

    /// <summary>The fish's index within its team (0 the hunter or the free fish, 1–3 the prey or the parked).</summary>
    public int Rank(int fish) => _rank[fish];

    /// <summary>Whether fish j (1–3) of a team has been caught.</summary>
    public bool IsCaught(int team, int j) => j >= 1 && j < SurvivalLayout.FishPerTeam && _caught[team, j - 1];

    /// <summary>The cycle of a team's last catch, counted from the start of its half, or null if it caught none.</summary>
    public int? LastCatch(int team) => _lastCatch[team] == Never ? null : _lastCatch[team];

    /// <inheritdoc/>
    protected override bool HalfDone => Scores[Hunter] >= SurvivalLayout.CatchesPerHalf;

    /// <inheritdoc/>
    protected override string HalfTimeChange => "hunter and hunted swap";

    /// <inheritdoc/>
    public override void AfterDecisions(World world)
    {
        base.AfterDecisions(world);
        foreach (var f in world.Fish)
        {
            if (_rank[f.Index] >= 1 && f.Decision.VCode > SurvivalLayout.PreyMaxVCode)
            {
                f.Decision = new Decision(SurvivalLayout.PreyMaxVCode, f.Decision.TCode);
            }
        }
    }

    /// <inheritdoc/>
    protected override void OnStart(World world)
    {
        _rank = new int[world.Fish.Length];
        int[] next = [0, 0];
        foreach (var f in world.Fish)
        {
            _rank[f.Index] = next[f.Team]++;
        }

        PlaceAll(world);
    }

    /// <inheritdoc/>
    protected override bool Score(World world, ReadOnlySpan<ContactRecord> contacts)
    {
        int hunter = Hunter, prey = 1 - hunter;
        bool moved = false;
        foreach (ref readonly var c in contacts)
        {
            if (c.Pair.Kind != PairKind.FishFish || Scores[hunter] >= SurvivalLayout.CatchesPerHalf)
            {
                continue;
            }

            int a = c.Pair.A, b = c.Pair.B;
            int caught = IsHunter(world, a, hunter) ? b : IsHunter(world, b, hunter) ? a : -1;
            if (caught < 0)
            {
                continue;
            }

            var f = world.Fish[caught];
            int j = _rank[caught];
            if (f.Team != prey || j < 1 || f.OutOfPlay || _caught[prey, j - 1])
            {
                continue;
            }

            _caught[prey, j - 1] = true;
            Scores[hunter]++;
            _lastCatch[hunter] = world.Cycle - HalfStartCycle;
            Placement.Park(f, SurvivalLayout.CaughtPlace(j), 0f);
            moved = true;
            AddEvent(world.Cycle, "catch", hunter, caught, -1, 1, $"team {hunter} catches team {prey}'s fish {j} (+1)");
        }

        return moved;
    }

    /// <inheritdoc/>
    protected override bool OnHalfTime(World world)
    {
        PlaceAll(world);
        return true;
    }

    /// <inheritdoc/>
    protected override MatchOutcome Decide() => MatchOutcome.ByScore(Scores[0], Scores[1], () =>
        _lastCatch[0] != _lastCatch[1]
            ? new MatchOutcome(_lastCatch[0] < _lastCatch[1] ? 0 : 1, "equal catches, earlier last catch")
            : new MatchOutcome(-1, "tie"));

    /// <inheritdoc/>
    protected override void UpdateVariables(World world)
    {
        for (int team = 1; team >= 0; team--)
        {
            for (int j = 0; j < SurvivalLayout.FishPerTeam - 1; j++)
            {
                Variables.Set(Keys[team][j], _caught[team, j] ? 1 : 0);
            }
        }
    }

    private bool IsHunter(World world, int fish, int hunter) => world.Fish[fish].Team == hunter && _rank[fish] == 0 && !world.Fish[fish].OutOfPlay;

    // Every fish at the cycle-0 pose of the role its team has now (the hunting team takes the
    // scenario's team-0 poses, the hunted team team 1's); the hunting team's fish 1–3 are parked.
    private void PlaceAll(World world)
    {
        foreach (var f in world.Fish)
        {
            int role = f.Team == Hunter ? 0 : 1;
            var start = StartOf(role, _rank[f.Index]);
            if (role == 0 && _rank[f.Index] >= 1)
            {
                Placement.Park(f, start.Position, start.Heading);
            }
            else
            {
                Placement.Place(f, start.Position, start.Heading);
            }
        }
    }
}
