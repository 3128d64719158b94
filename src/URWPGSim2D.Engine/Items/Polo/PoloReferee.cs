using System.Globalization;
using URWPGSim2D.Collision.Pool;

namespace URWPGSim2D.Engine.Items.Polo;

/// <summary>
/// The rules of 水球 1v1/3v3/5v5, as the original's <c>Match1V1</c>, <c>Match3V3</c> and
/// <c>Match5V5</c>, after every cycle in the original's order:
/// <list type="bullet">
/// <item>Dead ball: the ball in a corner (within goal depth + r + 50 of an end line and r + 50 of a
/// side wall) with a fish of each team within 120 mm of it (or touching it) for 100 cycles in a row
/// goes to the nearest free-ball spot (±L/4, ±W/4), the fish beside it (event <c>dead-ball</c>).</item>
/// <item>Fouls, while the ball lies wholly in a team's forbidden zone: a fish of that team whose
/// centre stays in its own goal for more than 50 cycles is sent off; in 3v3 and 5v5, when three or
/// more of its fish have been in the forbidden zone for more than 50 cycles the last to enter is
/// sent off. In 5v5 a defender (fish 1, 2) beyond x = ±200 into the other half or a forward
/// (fish 3, 4) back beyond it into its own half is sent off at once. Sent off = parked out of play
/// beside a side wall for 80 cycles (1v1) or 100, then back just inside that wall (events <c>foul</c>, <c>sent-off</c>).</item>
/// <item>Goal: the ball wholly inside a goal scores for the other team (event <c>goal</c>); everyone
/// back to the kick-off poses, the conceding team kicking off.</item>
/// <item>Time: half time at the middle of each timed period (ends change); a tie after normal time
/// plays 3 minutes of extra time, then penalties (one 20 s kick per team and round, team 0 first,
/// up to five rounds, decided after a round), then a 5-minute clutch shot whose first goal wins.</item>
/// </list>
/// <c>HtMissionVariables</c>: <c>CompetitionPeriod</c> (0 normal, 1 extra time, 2 penalties, 3 clutch shot).
/// </summary>
internal sealed class PoloReferee : ItemReferee
{
    /// <summary>Cycles a fish may stay in its goal or forbidden zone before it fouls (5 s).</summary>
    public const int FoulCycles = 50;

    /// <summary>Cycles of a dead-ball stand-off before the restart (10 s).</summary>
    public const int DeadBallCycles = 100;

    /// <summary>Distance from the ball centre within which a fish contests it, mm.</summary>
    public const float ContestDistance = 120f;

    /// <summary>Extra time, cycles (3 minutes).</summary>
    public const int ExtraTimeCycles = 1800;

    /// <summary>One penalty kick, cycles (20 s).</summary>
    public const int KickCycles = 200;

    /// <summary>Rounds of penalties before the clutch shot.</summary>
    public const int PenaltyRounds = 5;

    /// <summary>Clutch shot, cycles (5 minutes).</summary>
    public const int ClutchShotCycles = 3000;

    private readonly int _perTeam;
    private readonly float _length;
    private readonly float _width;
    private readonly int[][] _members = [[], []];
    private readonly int[] _inGoal;
    private readonly int[] _inZone;
    private readonly int[] _sentOff;
    private readonly bool[] _armed;
    private readonly int _sendOffCycles;
    private int _periodStart;
    private int _periodLength;
    private bool _halfTimeDone;
    private int _deadBall;
    private int _kick = -1;
    private string _rule = "higher score";

    /// <summary>Creates the referee of one match of <paramref name="cycles"/> cycles of normal time.</summary>
    public PoloReferee(PoloItem item, ScenarioDefinition scenario, int cycles)
        : base(item, scenario, cycles, halves: 1)
    {
        _perTeam = item.PerTeam;
        _length = scenario.FieldLength;
        _width = scenario.FieldWidth;
        int n = scenario.Fish.Count;
        _inGoal = new int[n];
        _inZone = new int[n];
        _sentOff = new int[n];
        _armed = new bool[n];
        _sendOffCycles = _perTeam == 1 ? 80 : 100;
        _periodLength = cycles;
        var lists = new[] { new List<int>(), new List<int>() };
        for (int i = 0; i < n; i++)
        {
            lists[scenario.Fish[i].Team].Add(i);
        }

        _members = [lists[0].ToArray(), lists[1].ToArray()];
    }

    /// <inheritdoc/>
    internal override bool CanRestart => true;

    /// <summary>The current phase.</summary>
    public PoloPeriod Period { get; private set; }

    /// <summary>The team playing from the left end now (it attacks the right goal).</summary>
    public int LeftTeam { get; private set; }

    /// <summary>The end a team attacks now: +1 the right goal, −1 the left.</summary>
    public int AttackSide(int team) => team == LeftTeam ? 1 : -1;

    /// <summary>Cycles a fish still has to sit out, 0 when it plays.</summary>
    public int SentOffCycles(int fish) => _sentOff[fish];

    /// <summary>During penalties, the team taking the current kick, otherwise −1.</summary>
    public int Kicker => Period == PoloPeriod.PenaltyKickTime && _kick >= 0 ? _kick % 2 : -1;

    /// <inheritdoc/>
    /// <remarks>A match of no cycles (<c>--cycles 0</c>: the layout alone) plays no deciders either.</remarks>
    public override int MaxCycles => Cycles == 0 ? 0 : Cycles + ExtraTimeCycles + (2 * PenaltyRounds * KickCycles) + ClutchShotCycles;

    /// <inheritdoc/>
    protected override bool PlaysOn => true;

    /// <inheritdoc/>
    protected override bool Score(World world, ReadOnlySpan<ContactRecord> contacts)
    {
        bool moved = SitOut(world);
        if (Period != PoloPeriod.PenaltyKickTime)
        {
            moved |= DeadBall(world, contacts);
            moved |= Fouls(world);
        }

        moved |= Goal(world);
        if (!MatchDone)
        {
            moved |= Clock(world);
        }

        return moved;
    }

    /// <inheritdoc/>
    protected override MatchOutcome Decide() =>
        Scores[0] == Scores[1] ? new MatchOutcome(-1, "tie") : new MatchOutcome(Scores[0] > Scores[1] ? 0 : 1, _rule);

    /// <inheritdoc/>
    protected override void UpdateVariables(World world) => Variables.Set("CompetitionPeriod", (int)Period);

    /// <inheritdoc/>
    private protected override void OnRestart()
    {
        Array.Clear(_inGoal);
        Array.Clear(_inZone);
        Array.Clear(_sentOff);
        Array.Clear(_armed);
        _periodStart = 0;
        _periodLength = Cycles;
        _halfTimeDone = false;
        _deadBall = 0;
        _kick = -1;
        _rule = "higher score";
        Period = PoloPeriod.NormalTime;
        LeftTeam = 0;
    }

    private bool DeadBall(World world, ReadOnlySpan<ContactRecord> contacts)
    {
        var ball = world.Balls[0];
        if (!PoloLayout.BallInCorner(ball.Position, ball.Radius, _length, _width))
        {
            _deadBall = 0;
            return false;
        }

        bool a = Contests(world, contacts, 0), b = Contests(world, contacts, 1);
        _deadBall = a && b ? _deadBall + 1 : 0;
        if (_deadBall < DeadBallCycles)
        {
            return false;
        }

        _deadBall = 0;
        Vector2 spot = PoloLayout.FreeBallSpot(ball.Position, _length, _width);
        Placement.Place(ball, spot);
        for (int side = 0; side < 2; side++)
        {
            int team = side == 0 ? LeftTeam : 1 - LeftTeam;
            float sign = side == 0 ? -1f : 1f;
            var members = _members[team];
            for (int j = 0; j < members.Length; j++)
            {
                var f = world.Fish[members[j]];
                if (f.OutOfPlay || !MovesForFreeBall(f, spot))
                {
                    continue;
                }

                float z = _perTeam == 5 && spot.X * sign < 0f ? (j == 0 ? -3f : 3f * (j - 3)) : 3f * (j - 1);
                Placement.Place(f, new Vector2(spot.X + (sign * (f.Size.Length + ball.Radius)), spot.Y + (z * f.Size.Width)), side == 0 ? 0f : MathF.PI);
            }
        }

        AddEvent(world.Cycle, "dead-ball", -1, -1, 0, double.NaN, $"dead ball: restart at ({spot.X:0}, {spot.Y:0})");
        return true;
    }

    // 1v1 and 3v3 move every fish beside the spot; 5v5 only those on the spot's side of the centre circle.
    private bool MovesForFreeBall(FishState f, Vector2 spot) =>
        _perTeam != 5 || (spot.X < 0f ? f.Position.X < -PoloLayout.CentreCircleRadius : f.Position.X > PoloLayout.CentreCircleRadius);

    private bool Contests(World world, ReadOnlySpan<ContactRecord> contacts, int team)
    {
        var ball = world.Balls[0];
        foreach (int i in _members[team])
        {
            var f = world.Fish[i];
            if (!f.OutOfPlay && Vector2.Distance(f.Position, ball.Position) <= ContestDistance)
            {
                return true;
            }
        }

        foreach (ref readonly var c in contacts)
        {
            if (c.Pair.Kind == PairKind.FishBall && c.Pair.B == 0 && world.Fish[c.Pair.A].Team == team)
            {
                return true;
            }
        }

        return false;
    }

    private bool Fouls(World world)
    {
        bool moved = false;
        var ball = world.Balls[0];
        for (int team = 0; team < 2; team++)
        {
            int own = team == LeftTeam ? -1 : 1;
            var members = _members[team];
            if (!PoloLayout.BallInForbiddenZone(ball.Position, ball.Radius, _length, own))
            {
                foreach (int i in members)
                {
                    _inGoal[i] = 0;
                    _inZone[i] = 0;
                }

                continue;
            }

            int inZoneTooLong = 0;
            int last = -1;
            foreach (int i in members)
            {
                var f = world.Fish[i];
                if (f.OutOfPlay)
                {
                    continue;
                }

                _inGoal[i] = PoloLayout.FishInGoal(f.Position, _length, own) ? _inGoal[i] + 1 : 0;
                _inZone[i] = PoloLayout.FishInForbiddenZone(f.Position, _length, own) ? _inZone[i] + 1 : 0;
                if (_inZone[i] > FoulCycles)
                {
                    inZoneTooLong++;
                    last = last < 0 || _inZone[i] < _inZone[last] ? i : last;
                }
            }

            foreach (int i in members)
            {
                if (!world.Fish[i].OutOfPlay && _inGoal[i] > FoulCycles)
                {
                    moved |= SendOff(world, i, "in its own goal for more than 5 s");
                }
            }

            if (_perTeam >= 3 && inZoneTooLong >= 3 && !world.Fish[last].OutOfPlay)
            {
                moved |= SendOff(world, last, "a third fish in its own forbidden zone for more than 5 s");
            }
        }

        if (_perTeam == 5)
        {
            moved |= RoleFouls(world);
        }

        return moved;
    }

    // 5v5: defenders (fish 1, 2) stay on their side of x = ±200, forwards (3, 4) on the other; a fish
    // is held to its area once it has been inside it since its last kick-off or return.
    private bool RoleFouls(World world)
    {
        bool moved = false;
        for (int team = 0; team < 2; team++)
        {
            float toward = AttackSide(team);
            var members = _members[team];
            for (int j = 1; j < members.Length && j < 5; j++)
            {
                var f = world.Fish[members[j]];
                if (f.OutOfPlay)
                {
                    continue;
                }

                float x = f.Position.X * toward; // > 0: in the half the team attacks
                bool inside = j <= 2 ? x <= PoloLayout.CentreCircleRadius : x >= -PoloLayout.CentreCircleRadius;
                if (inside)
                {
                    _armed[members[j]] = true;
                }
                else if (_armed[members[j]])
                {
                    moved |= SendOff(world, members[j], j <= 2 ? "a defender out of its half" : "a forward back in its own half");
                }
            }
        }

        return moved;
    }

    private bool SendOff(World world, int fish, string why)
    {
        var f = world.Fish[fish];
        int team = f.Team;
        int count = 0;
        foreach (int i in _members[team])
        {
            count += _sentOff[i] > 0 ? 1 : 0;
        }

        count++;
        float top = -_width / 2f;
        float w2 = 2f * f.Size.Width;
        Vector2 place;
        float heading;
        if (_perTeam == 5)
        {
            float x = (0.25f + (0.5f * (count - 0.5f) * (count % 2 == 0 ? 1f : -1f))) * w2;
            bool above = team == LeftTeam;
            place = new Vector2(x, above ? top - (f.Size.Length / 2f) : -top + (f.Size.Length / 2f));
            heading = above ? MathF.PI / 2f : -MathF.PI / 2f;
        }
        else
        {
            place = new Vector2((team == LeftTeam ? -1f : 1f) * count * w2, top - (f.Size.Length / 2f));
            heading = MathF.PI / 2f;
        }

        Placement.Park(f, place, heading);
        _sentOff[fish] = _sendOffCycles;
        _inGoal[fish] = 0;
        _inZone[fish] = 0;
        _armed[fish] = false;
        AddEvent(world.Cycle, "foul", team, fish, -1, double.NaN, $"team {team} fish {fish} fouls: {why}");
        AddEvent(world.Cycle, "sent-off", team, fish, -1, double.NaN, $"fish {fish} sent off for {_sendOffCycles / 10} s");
        return true;
    }

    // Sent-off fish count down; a fish whose time is served comes back just inside the side wall it waited at.
    private bool SitOut(World world)
    {
        bool moved = false;
        for (int i = 0; i < _sentOff.Length; i++)
        {
            if (_sentOff[i] == 0 || --_sentOff[i] > 0)
            {
                continue;
            }

            var f = world.Fish[i];
            float edge = (_width / 2f) - (f.Size.Length / 2f) - f.Size.Head - 20f;
            Placement.Place(f, new Vector2(f.Position.X, f.Position.Y < 0f ? -edge : edge), f.Heading);
            moved = true;
        }

        return moved;
    }

    private bool Goal(World world)
    {
        var ball = world.Balls[0];
        int side = PoloLayout.BallInGoal(ball.Position, ball.Radius, _length, -1) ? -1
            : PoloLayout.BallInGoal(ball.Position, ball.Radius, _length, 1) ? 1 : 0;
        if (side == 0)
        {
            return false;
        }

        int scorer = side > 0 ? LeftTeam : 1 - LeftTeam;
        if (Period == PoloPeriod.PenaltyKickTime && scorer != Kicker)
        {
            // Only the kicker can score a penalty; the kick is over.
            NextKick(world);
            return true;
        }

        Scores[scorer]++;
        AddEvent(world.Cycle, "goal", scorer, -1, 0, 1, $"team {scorer} scores ({Scores[0]}:{Scores[1]})");
        if (Period == PoloPeriod.ClutchShotTime)
        {
            _rule = "clutch shot (first goal)";
            MatchDone = true;
            return false;
        }

        if (Period == PoloPeriod.PenaltyKickTime)
        {
            NextKick(world);
            return true;
        }

        KickOff(world, kicker: 1 - scorer);
        return true;
    }

    private bool Clock(World world)
    {
        int elapsed = world.Cycle - _periodStart;
        if (Period == PoloPeriod.PenaltyKickTime)
        {
            return elapsed >= KickCycles && NextKick(world);
        }

        if (!_halfTimeDone && elapsed >= _periodLength / 2 && elapsed < _periodLength)
        {
            _halfTimeDone = true;
            LeftTeam = 1 - LeftTeam;
            AddEvent(world.Cycle, "half-time", -1, -1, -1, double.NaN, $"half time of {PeriodName(Period)}: teams change ends");
            KickOff(world, kicker: LeftTeam);
            return true;
        }

        if (elapsed < _periodLength)
        {
            return false;
        }

        if (Scores[0] != Scores[1] || Period == PoloPeriod.ClutchShotTime)
        {
            _rule = Period == PoloPeriod.NormalTime ? "higher score" : "higher score after extra time";
            MatchDone = true;
            return false;
        }

        if (Period == PoloPeriod.NormalTime)
        {
            StartPeriod(world, PoloPeriod.ExtraTime, ExtraTimeCycles);
            KickOff(world, kicker: LeftTeam);
            return true;
        }

        StartPeriod(world, PoloPeriod.PenaltyKickTime, KickCycles);
        _kick = -1;
        return NextKick(world);
    }

    private void StartPeriod(World world, PoloPeriod period, int length)
    {
        Period = period;
        _periodStart = world.Cycle;
        _periodLength = length;
        _halfTimeDone = false;
        AddEvent(world.Cycle, "period", -1, -1, -1, double.NaN, $"{Scores[0]}:{Scores[1]}, {PeriodName(period)} follows");
    }

    // Ends the current kick (if any) and sets up the next one, or decides after a full round.
    private bool NextKick(World world)
    {
        if (_kick >= 0 && _kick % 2 == 1)
        {
            int round = (_kick / 2) + 1;
            if (Scores[0] != Scores[1])
            {
                _rule = "penalties";
                MatchDone = true;
                return false;
            }

            if (round >= PenaltyRounds)
            {
                foreach (var f in world.Fish)
                {
                    f.OutOfPlay = false;
                }

                StartPeriod(world, PoloPeriod.ClutchShotTime, ClutchShotCycles);
                LeftTeam = 0;
                KickOff(world, kicker: LeftTeam);
                return true;
            }
        }

        _kick++;
        _periodStart = world.Cycle;
        int kicker = _kick % 2;
        int side = AttackSide(kicker);
        var ball = world.Balls[0];
        Vector2 spot = PoloLayout.PenaltySpot(_length, side);
        Placement.Place(ball, spot);
        for (int team = 0; team < 2; team++)
        {
            var members = _members[team];
            for (int j = 0; j < members.Length; j++)
            {
                var f = world.Fish[members[j]];
                _sentOff[members[j]] = 0;
                if (j == 0)
                {
                    // The kicker's fish 0 behind the ball facing the goal; the keeper on its goal line.
                    Vector2 at = team == kicker
                        ? new Vector2(spot.X - (side * 1.1f * f.Size.Length), 0f)
                        : new Vector2(side * ((_length / 2f) - (1.8f * f.Size.Length)), 0f);
                    Placement.Place(f, at, team == kicker ? (side > 0 ? 0f : MathF.PI) : (side > 0 ? MathF.PI : 0f));
                }
                else
                {
                    float z = (team == kicker ? 3f : 1f) * f.Size.Width * (j % 2 == 1 ? 1f : -1f) * ((j + 1) / 2);
                    Placement.Park(f, new Vector2(0f, z), side > 0 ? 0f : MathF.PI);
                }
            }
        }

        AddEvent(world.Cycle, "penalty", kicker, -1, 0, double.NaN, $"penalty {(_kick / 2) + 1} of team {kicker}");
        return true;
    }

    // Every fish to its kick-off pose for the current ends (5v5: the kicking-off team's forwards nearer the centre), ball at the centre, fouls cleared.
    private void KickOff(World world, int kicker)
    {
        for (int team = 0; team < 2; team++)
        {
            bool left = team == LeftTeam;
            var members = _members[team];
            var size = world.Fish[members[0]].Size;
            for (int j = 0; j < members.Length && j < _perTeam; j++)
            {
                int i = members[j];
                var pose = PoloLayout.KickOffPose(_perTeam, left, kicksOff: team == kicker, size, j);
                Placement.Place(world.Fish[i], pose.Position, pose.Heading);
                _sentOff[i] = 0;
                _inGoal[i] = 0;
                _inZone[i] = 0;
                _armed[i] = false;
            }
        }

        Placement.Place(world.Balls[0], Vector2.Zero);
        _deadBall = 0;
    }

    private static string PeriodName(PoloPeriod p) => p switch
    {
        PoloPeriod.NormalTime => "normal time",
        PoloPeriod.ExtraTime => "extra time",
        PoloPeriod.PenaltyKickTime => "penalties",
        _ => "the clutch shot",
    };
}
