using URWPGSim2D.Collision.Fish;
using URWPGSim2D.Collision.Motion;
using URWPGSim2D.Engine.Items;
using URWPGSim2D.Engine.Items.PlainScene;
using URWPGSim2D.Engine.Teams;

namespace URWPGSim2D.Engine.Matches;

/// <summary>
/// A match in progress. <see cref="Step"/> plays one 100 ms cycle: strategies decide from a
/// read-only snapshot of the last cycle → fish locomotion → ball locomotion → motion with collision
/// detection and response (<see cref="CycleMotion"/>) → rules (<see cref="Rules"/>: the competition
/// item's referee, or the plain scene's goal rule). Everything iterates by index;
/// the noise generators are seeded, so the same scenario and seed replay the same match. After the
/// first cycles a step allocates nothing (built-in strategies).
/// </summary>
public sealed class Match
{
    private readonly SeededRandom? _motionNoise;
    private readonly SeededRandom? _viewNoise;
    private readonly MatchSnapshotWriter _view;
    private int _observedCycle = -1;

    /// <summary>Creates a match.</summary>
    /// <param name="world">The pool and its bodies.</param>
    /// <param name="teams">Who decides for the fish.</param>
    /// <param name="noise">Whether the reference's motion and observation noise is on.</param>
    /// <param name="seed">Seed of the noise generators.</param>
    /// <param name="referee">The rules of a competition item, or null for the plain scene's goal rule (<see cref="PlainSceneReferee"/>).</param>
    public Match(World world, IMatchTeams teams, bool noise, ulong seed, ItemReferee? referee = null)
    {
        World = world;
        Teams = teams;
        Referee = referee;
        Seed = seed;
        Rules = referee ?? new PlainSceneReferee(0);
        Contacts = new ContactLog(world.Fish.Length + world.Balls.Length);
        _view = new MatchSnapshotWriter(world.Fish.Length, world.Balls.Length, world.Obstacles, world.Field.Length, world.Field.Width);
        Motion = new CycleMotion(world, Contacts);
        Rules.Start(world);
        if (noise)
        {
            _motionNoise = new SeededRandom(seed);
            _viewNoise = new SeededRandom(seed ^ 0x5DEECE66DUL);
        }
    }

    /// <summary>The pool and its bodies.</summary>
    public World World { get; }

    /// <summary>The match's seed (its noise and its item's random placements): the same seed plays the same match.</summary>
    public ulong Seed { get; private set; }

    /// <summary>Who decides for the fish.</summary>
    public IMatchTeams Teams { get; }

    /// <summary>What strategies see.</summary>
    public MatchSnapshot Snapshot => _view.Snapshot;

    /// <summary>The contacts of the last cycle and the match's counts.</summary>
    public ContactLog Contacts { get; }

    /// <summary>Motion interpolation and contact handling.</summary>
    public CycleMotion Motion { get; }

    /// <summary>The competition item's referee, or null for a plain scene.</summary>
    public ItemReferee? Referee { get; }

    /// <summary>The rules the match is judged by, the one owner of its score and events: <see cref="Referee"/>, or the plain scene's goal rule.</summary>
    public ItemReferee Rules { get; }

    /// <summary>Whether the match is over (never for a plain scene: it plays every cycle asked for).</summary>
    public bool IsOver => Rules.IsOver;

    /// <summary>Totals for the summary.</summary>
    public MatchStatistics Statistics { get; } = new();

    /// <summary>Plays one cycle.</summary>
    public void Step()
    {
        Observe();
        Teams.Decide(Snapshot, World.Fish);
        Rules.AfterDecisions(World);
        Contacts.BeginCycle();
        Locomotion.Apply(World, _motionNoise, (World.Cycle + 1) * 0.1);
        Motion.Run();
        World.Cycle++;
        if (Rules.Judge(World, Contacts.Cycle))
        {
            Motion.Settle();
        }

        Locomotion.Finish(World);
        Statistics.Record(World.Cycle, Motion.SubSteps, Motion.Events, Motion.LeftoverOverlap);
    }

    /// <summary>
    /// Fills <see cref="Snapshot"/> with the current cycle (once a cycle: <see cref="Step"/> then
    /// decides from the same snapshot, its noise drawn once), and returns it: what the strategies
    /// will see, read before the cycle is played (a learning environment's observation).
    /// </summary>
    public MatchSnapshot Observe()
    {
        if (_observedCycle != World.Cycle)
        {
            FillSnapshot();
            _observedCycle = World.Cycle;
        }

        return Snapshot;
    }

    /// <summary>
    /// Whether <see cref="Restart"/> can put this match back to its start: an item whose referee
    /// restarts in place (polo), and built-in or pushed strategies on every seat.
    /// </summary>
    public bool CanRestart => Referee is { CanRestart: true } && Teams is StrategyTeams { CanRestart: true };

    /// <summary>
    /// Puts the match back to cycle 0 of a new match of the same scenario, teams and noise with
    /// <paramref name="seed"/>, every buffer kept: the bodies at their start poses and at rest, the
    /// referee, strategies, counts and noise as new, so that it then plays exactly what a match
    /// built anew plays. Allocates nothing.
    /// </summary>
    /// <param name="seed">The seed of the noise (the item's layout must not depend on it: <see cref="CanRestart"/>).</param>
    /// <exception cref="System.InvalidOperationException">The match cannot restart in place (<see cref="CanRestart"/>).</exception>
    public void Restart(ulong seed)
    {
        if (!CanRestart)
        {
            throw new System.InvalidOperationException("this match cannot restart in place (an item or a strategy without a restart)");
        }

        var scenario = Referee!.Scenario;
        World.Cycle = 0;
        Motion.Restart();
        for (int i = 0; i < World.Fish.Length; i++)
        {
            var d = scenario.Fish[i];
            World.Fish[i].Restart(d.Position, d.Heading, d.TailPhase);
        }

        for (int i = 0; i < World.Balls.Length; i++)
        {
            World.Balls[i].Restart(scenario.Balls[i].Velocity);
        }

        Seed = seed;
        _motionNoise?.Reseed(seed);
        _viewNoise?.Reseed(seed ^ 0x5DEECE66DUL);
        Contacts.Restart();
        Statistics.Restart();
        ((StrategyTeams)Teams).Restart();
        _observedCycle = -1;
        Rules.RestartInPlace(World);
    }

    /// <summary>The teams of the match: 2, or more when a fish plays for a team numbered 2 or higher (four-teams).</summary>
    public int TeamCount => World.TeamCount;

    /// <summary>The labels of the strategies playing for <paramref name="team"/>, joined with "+" ("no fish" for a team without fish).</summary>
    public string TeamLabel(int team) => Teams.TeamLabel(team);

    private void FillSnapshot()
    {
        _view.SetHeader(World.Cycle, Rules.Scores);
        if (Referee is { } item)
        {
            _view.SetItem(item.Item.ChineseName, item.Variables, item.Cycles);
            _view.SetSidesSwapped(item.SidesSwapped);
        }

        var fish = _view.Fish;
        for (int i = 0; i < fish.Length; i++)
        {
            var f = World.Fish[i];
            FishPose pose = f.Pose;
            Vector2 position = pose.Position;
            float heading = pose.Heading;
            if (_viewNoise is not null)
            {
                position += new Vector2(_viewNoise.NextSigned(), _viewNoise.NextSigned()) * 30f;
                heading = Angle.Wrap(heading + (_viewNoise.NextSigned() * (5f * System.MathF.PI / 180f)));
            }

            fish[i] = new FishView(i, f.Team, position, heading, f.Speed.Value, f.Turn.Value, f.Size.Length, f.Size.Head, f.Decision)
            {
                Width = f.Size.Width, Joint1 = pose.Joint1, Joint2 = pose.Joint2, Joint3 = pose.Joint3,
                TailLength1 = f.Size.Joint1, TailLength2 = f.Size.Joint2, TailLength3 = f.Size.Joint3,
            };
        }

        var balls = _view.Balls;
        for (int i = 0; i < balls.Length; i++)
        {
            var b = World.Balls[i];
            Vector2 position = b.Position;
            if (_viewNoise is not null)
            {
                position += new Vector2(_viewNoise.NextSigned(), _viewNoise.NextSigned()) * 30f;
            }

            balls[i] = new BallView(i, position, b.Velocity, b.Radius);
        }
    }
}
