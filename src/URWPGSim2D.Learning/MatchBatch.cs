using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;
using URWPGSim2D.Collision.BroadPhase;
using URWPGSim2D.Engine.BuiltInStrategies;
using URWPGSim2D.Engine.Items;
using URWPGSim2D.Engine.Items.Catalog;
using URWPGSim2D.Engine.Matches;
using URWPGSim2D.Engine.Teams;
using URWPGSim2D.Strategies;

namespace URWPGSim2D.Learning;

/// <summary>
/// <see cref="Count"/> matches of one competition item, stepped together for reinforcement learning:
/// in each, one team plays the actions it is given and the other plays an opponent strategy. Each
/// match is the match <c>run --item ITEM --seed SEED --cycles CYCLES --strategy TEAM=… --strategy OTHER=OPPONENT</c>
/// plays with the same decisions. <see cref="Reset"/> starts every match from a seed; <see cref="Step"/>
/// plays one cycle of each and writes observations, rewards and episode ends into the caller's
/// buffers, allocating nothing. A match that ended is started again at the next step (its action is
/// then ignored): the Gymnasium vector convention "next-step autoreset".
/// </summary>
/// <remarks>
/// <para>Observation of a match, <see cref="ObservationSize"/> floats: for every fish of the match
/// (by index) x/1000, y/1000 (metres), cos and sin of its heading, speed/1000; for every ball x/1000,
/// y/1000, vx/1000, vy/1000; then the time fraction min(cycle / cycles, 1). Fish and balls are as the
/// strategies see them (the item's observation noise included). Action: <see cref="ActionSize"/>
/// integers 0..15, a speed code and a turn code per fish of the team, in the order of the fish's
/// indices. Reward: the change of (own score − other team's score) during the cycle.
/// Terminated: the match ended (its item decided it). Truncated: <c>cycles</c> cycles (or the
/// reset's <c>maxSteps</c>) were played and the match plays on.</para>
/// <para>Not thread-safe: one thread steps a batch.</para>
/// </remarks>
public sealed class MatchBatch
{
    /// <summary>The opponent specs a batch accepts: the built-in strategies and the item's demo strategy.</summary>
    public static IReadOnlyList<string> Opponents { get; } = ["idle", "chase-ball", "demo"];

    private readonly CompetitionItem _item;
    private readonly Match?[] _matches;
    private readonly PushedDecisions?[] _teams;
    private readonly ulong[] _seeds;
    private readonly int[] _difference;
    private readonly bool[] _ended;
    private int _maxSteps;
    private bool _started;

    /// <summary>Creates <paramref name="count"/> matches of <paramref name="item"/> (started by <see cref="Reset"/>).</summary>
    /// <param name="item">The item's slug or original name (<c>run --list-items</c>), e.g. "polo-1v1".</param>
    /// <param name="opponent">What the other team plays: "idle", "chase-ball" or "demo" (the item's demo strategy).</param>
    /// <param name="count">Matches in the batch, 1 to 65,536.</param>
    /// <param name="team">The team the actions play: 0, or 1 in an item of two teams or more.</param>
    /// <param name="cycles">Cycles of a match (an item's halves depend on it), 1 or more: an episode never lasts longer.</param>
    /// <exception cref="ArgumentException">An argument is unknown or out of range (the message names it and its value).</exception>
    public MatchBatch(string item, string opponent = "chase-ball", int count = 1, int team = 0, int cycles = 600)
    {
        ArgumentNullException.ThrowIfNull(item);
        ArgumentNullException.ThrowIfNull(opponent);
        _item = ItemRegistry.Find(item) ?? throw new ArgumentException(
            $"item: unknown item \"{item}\" (one of {string.Join(", ", ItemRegistry.All.Select(i => i.Slug))})", nameof(item));
        if (!Opponents.Contains(opponent))
        {
            throw new ArgumentException($"opponent: unknown opponent \"{opponent}\" (one of {string.Join(", ", Opponents)})", nameof(opponent));
        }

        if (count < 1 || count > 65536)
        {
            throw new ArgumentException(Invariant($"count: {count} matches, expected 1 to 65536"), nameof(count));
        }

        if (team < 0 || team >= Math.Max(1, _item.TeamCount))
        {
            throw new ArgumentException(Invariant($"team: {team}, expected 0 to {_item.TeamCount - 1} in {_item.Slug}"), nameof(team));
        }

        if (cycles < 1)
        {
            throw new ArgumentException(Invariant($"cycles: {cycles}, expected 1 or more"), nameof(cycles));
        }

        Item = _item.Slug;
        Opponent = opponent;
        Count = count;
        Team = team;
        Cycles = cycles;
        var scenario = _item.CreateScenario(0);
        FishCount = scenario.Fish.Count;
        BallCount = scenario.Balls.Count;
        TeamFish = scenario.Fish.Count(f => f.Team == team);
        ObservationSize = (5 * FishCount) + (4 * BallCount) + 1;
        ActionSize = 2 * TeamFish;
        _matches = new Match?[count];
        _teams = new PushedDecisions?[count];
        _seeds = new ulong[count];
        _difference = new int[count];
        _ended = new bool[count];
    }

    /// <summary>The item's slug.</summary>
    public string Item { get; }

    /// <summary>What the other team plays.</summary>
    public string Opponent { get; }

    /// <summary>Matches in the batch.</summary>
    public int Count { get; }

    /// <summary>The team the actions play.</summary>
    public int Team { get; }

    /// <summary>Cycles of a match: the longest episode.</summary>
    public int Cycles { get; }

    /// <summary>Fish of a match (every team's).</summary>
    public int FishCount { get; }

    /// <summary>Balls of a match.</summary>
    public int BallCount { get; }

    /// <summary>Fish of the team the actions play.</summary>
    public int TeamFish { get; }

    /// <summary>Floats of one match's observation: 5 per fish, 4 per ball, 1 for the time.</summary>
    public int ObservationSize { get; }

    /// <summary>Integers of one match's action: 2 per fish of the team (speed code, turn code).</summary>
    public int ActionSize { get; }

    /// <summary>
    /// Starts every match: match <c>i</c> from <paramref name="seeds"/>[i] (a match that ends is
    /// started again from a seed drawn from its last one, <see cref="NextSeed"/>), and writes the
    /// first observations.
    /// </summary>
    /// <param name="seeds">One seed per match.</param>
    /// <param name="observations"><see cref="Count"/> × <see cref="ObservationSize"/> floats, written.</param>
    /// <param name="maxSteps">Steps after which an episode is truncated (when below <c>cycles</c>), or 0 for none.</param>
    /// <exception cref="ArgumentException">A buffer has the wrong length, or <paramref name="maxSteps"/> is negative.</exception>
    public void Reset(ReadOnlySpan<ulong> seeds, Span<float> observations, int maxSteps = 0)
    {
        Expect(nameof(seeds), seeds.Length, Count, "one seed per match");
        Expect(nameof(observations), observations.Length, Count * ObservationSize, Invariant($"{Count} matches × {ObservationSize}"));
        if (maxSteps < 0)
        {
            throw new ArgumentException(Invariant($"maxSteps: {maxSteps}, expected 0 (none) or more"), nameof(maxSteps));
        }

        _maxSteps = maxSteps;
        for (int i = 0; i < Count; i++)
        {
            Start(i, seeds[i]);
            Observe(i, observations.Slice(i * ObservationSize, ObservationSize));
        }

        _started = true;
    }

    /// <summary>
    /// Plays one cycle of every match with <paramref name="actions"/>, and writes each one's
    /// observation, reward and episode end. A match that ended at the last step is started again
    /// instead (its action ignored): its observation is then the new episode's first, its reward 0,
    /// and neither flag is set. Allocates nothing (the referees record their events without text,
    /// <see cref="ItemReferee.EventTexts"/>), restarting a polo match included (it is put back to its
    /// start in place); a match of another item is built anew when it restarts.
    /// </summary>
    /// <param name="actions"><see cref="Count"/> × <see cref="ActionSize"/> integers 0..15: per match, a speed code and a turn code per fish of the team.</param>
    /// <param name="observations"><see cref="Count"/> × <see cref="ObservationSize"/> floats, written.</param>
    /// <param name="rewards"><see cref="Count"/> floats, written.</param>
    /// <param name="terminated"><see cref="Count"/> flags, written: the match ended.</param>
    /// <param name="truncated"><see cref="Count"/> flags, written: the episode was cut at its length and the match plays on.</param>
    /// <exception cref="ArgumentException">A buffer has the wrong length or an action is not 0..15 (nothing is played then).</exception>
    /// <exception cref="InvalidOperationException">No <see cref="Reset"/> yet.</exception>
    public void Step(ReadOnlySpan<int> actions, Span<float> observations, Span<float> rewards, Span<bool> terminated, Span<bool> truncated)
    {
        Expect(nameof(actions), actions.Length, Count * ActionSize, "matches × action size");
        Expect(nameof(observations), observations.Length, Count * ObservationSize, "matches × observation size");
        Expect(nameof(rewards), rewards.Length, Count, "one per match");
        Expect(nameof(terminated), terminated.Length, Count, "one per match");
        Expect(nameof(truncated), truncated.Length, Count, "one per match");
        for (int j = 0; j < actions.Length; j++)
        {
            if ((uint)actions[j] > 15u)
            {
                throw BadAction(j, actions[j]);
            }
        }

        if (!_started)
        {
            throw new InvalidOperationException("step before reset: call Reset first");
        }

        for (int i = 0; i < Count; i++)
        {
            var obs = observations.Slice(i * ObservationSize, ObservationSize);
            if (_ended[i])
            {
                Start(i, NextSeed(_seeds[i]));
                Observe(i, obs);
                rewards[i] = 0f;
                terminated[i] = false;
                truncated[i] = false;
                continue;
            }

            var match = _matches[i]!;
            var pending = _teams[i]!.Pending;
            var action = actions.Slice(i * ActionSize, ActionSize);
            for (int k = 0; k < pending.Length; k++)
            {
                pending[k] = new Decision(action[2 * k], action[(2 * k) + 1]);
            }

            match.Step();
            int difference = Difference(match);
            rewards[i] = difference - _difference[i];
            _difference[i] = difference;
            int cycle = match.World.Cycle;
            bool over = match.IsOver || cycle >= (match.Referee?.MaxCycles ?? Cycles);
            bool cut = !over && (cycle >= Cycles || (_maxSteps > 0 && cycle >= _maxSteps));
            terminated[i] = over;
            truncated[i] = cut;
            _ended[i] = over || cut;
            Observe(i, obs);
        }
    }

    /// <summary>Each match's cycle, score and seed now.</summary>
    /// <param name="cycles"><see cref="Count"/> integers, written: cycles played in the episode.</param>
    /// <param name="goals"><see cref="Count"/> × 2 integers, written: team 0's and team 1's score.</param>
    /// <param name="seeds"><see cref="Count"/> seeds, written: the seed of each episode (<c>run --seed</c> replays it).</param>
    /// <exception cref="ArgumentException">A buffer has the wrong length.</exception>
    public void Info(Span<int> cycles, Span<int> goals, Span<ulong> seeds)
    {
        Expect(nameof(cycles), cycles.Length, Count, "one per match");
        Expect(nameof(goals), goals.Length, 2 * Count, "two per match");
        Expect(nameof(seeds), seeds.Length, Count, "one per match");
        for (int i = 0; i < Count; i++)
        {
            var match = _matches[i];
            cycles[i] = match?.World.Cycle ?? 0;
            var scores = match?.Rules.Scores ?? [];
            goals[2 * i] = scores.Length > 0 ? scores[0] : 0;
            goals[(2 * i) + 1] = scores.Length > 1 ? scores[1] : 0;
            seeds[i] = _seeds[i];
        }
    }

    /// <summary>The seed a match is started from after an episode from <paramref name="seed"/> (SplitMix64, kept below 2³¹ as <c>run --seed</c> is).</summary>
    /// <param name="seed">The last episode's seed.</param>
    public static ulong NextSeed(ulong seed)
    {
        ulong z = seed + 0x9E3779B97F4A7C15UL;
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9UL;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBUL;
        return (z ^ (z >> 31)) & 0x7FFFFFFFUL;
    }

    /// <summary>The match being played at <paramref name="index"/> (tests).</summary>
    internal Match MatchAt(int index) => _matches[index] ?? throw new InvalidOperationException("not started");

    private void Start(int i, ulong seed)
    {
        if (_matches[i] is { CanRestart: true } played)
        {
            // The same match back at its start with the new seed, every buffer kept: nothing allocated.
            played.Restart(seed);
            _seeds[i] = seed;
            _difference[i] = Difference(played);
            _ended[i] = false;
            return;
        }

        var pushed = new PushedDecisions(TeamFish);
        var teams = new IStrategy?[Math.Max(2, _item.TeamCount)];
        teams[Team] = pushed;
        if (_item.TeamCount > 1)
        {
            teams[1 - Team] = Opponent switch
            {
                "idle" => new IdleStrategy(),
                "chase-ball" => new ChaseBallStrategy(),
                _ => null, // the scenario's: every fish of an item plays its demo
            };
        }

        // Every broad phase plays the same match; with three to a dozen bodies trying every pair is the fastest.
        var match = MatchSetup.Create(_item.CreateScenario(seed), teams, seed: seed, cycles: Cycles, broadPhase: BroadPhaseKind.BruteForce);
        match.Rules.EventTexts = false; // the batch reads scores and ends, not the events' messages: a goal or half time allocates nothing
        _matches[i] = match;
        _teams[i] = pushed;
        _seeds[i] = seed;
        _difference[i] = Difference(match);
        _ended[i] = false;
    }

    private int Difference(Match match)
    {
        var scores = match.Rules.Scores;
        int own = Team < scores.Length ? scores[Team] : 0;
        int other = 1 - Team < scores.Length ? scores[1 - Team] : 0;
        return own - other;
    }

    private void Observe(int i, Span<float> obs)
    {
        var match = _matches[i]!;
        var s = match.Observe();
        int o = 0;
        foreach (ref readonly var f in s.Fish)
        {
            obs[o++] = (float)(f.Position.X / 1000.0);
            obs[o++] = (float)(f.Position.Y / 1000.0);
            obs[o++] = (float)Math.Cos(f.Heading);
            obs[o++] = (float)Math.Sin(f.Heading);
            obs[o++] = (float)(f.Speed / 1000.0);
        }

        foreach (ref readonly var b in s.Balls)
        {
            obs[o++] = (float)(b.Position.X / 1000.0);
            obs[o++] = (float)(b.Position.Y / 1000.0);
            obs[o++] = (float)(b.Velocity.X / 1000.0);
            obs[o++] = (float)(b.Velocity.Y / 1000.0);
        }

        obs[o] = (float)Math.Min((double)match.World.Cycle / Cycles, 1.0);
    }

    private ArgumentException BadAction(int j, int value) => new(
        Invariant($"actions[{j / ActionSize}][{j % ActionSize}]: {value}, expected an integer 0..15 ({(j % 2 == 0 ? "speed" : "turn")} code of fish {j % ActionSize / 2} of the team)"),
        "actions");

    private static void Expect(string name, int length, int expected, string what)
    {
        if (length != expected)
        {
            throw new ArgumentException(Invariant($"{name}: length {length}, expected {expected} ({what})"), name);
        }
    }

    private static string Invariant(FormattableString s) => s.ToString(CultureInfo.InvariantCulture);
}
