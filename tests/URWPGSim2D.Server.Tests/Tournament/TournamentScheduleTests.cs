namespace URWPGSim2D.Server.Tests.Tournament;

/// <summary>The schedules: every pairing as often as documented, seed by seed, and the same every time.</summary>
public sealed class TournamentScheduleTests
{
    [Fact]
    public void TwoTeamsPlayEveryOrderedPairOncePerSeed()
    {
        var s = new TournamentSchedule(teams: 2, entrants: 4, seeds: 3, firstSeed: 10);
        Assert.Equal(4 * 3 * 3, s.Matches.Count);
        Assert.Equal(Enumerable.Range(0, s.Matches.Count), s.Matches.Select(m => m.Index));
        foreach (var group in s.Matches.GroupBy(m => (m.Sides[0], m.Sides[1])))
        {
            Assert.NotEqual(group.Key.Item1, group.Key.Item2);
            Assert.Equal([10UL, 11UL, 12UL], group.Select(m => m.Seed).ToArray());
        }

        Assert.Equal(12, s.Matches.Select(m => (m.Sides[0], m.Sides[1])).Distinct().Count());
        Assert.True(s.Matches.Zip(s.Matches.Skip(1)).All(p => p.First.Seed <= p.Second.Seed)); // seed by seed
    }

    [Fact]
    public void OneTeamPlaysEveryEntrantOncePerSeed()
    {
        var s = new TournamentSchedule(teams: 1, entrants: 3, seeds: 2, firstSeed: 1);
        Assert.Equal([(1UL, 0), (1UL, 1), (1UL, 2), (2UL, 0), (2UL, 1), (2UL, 2)], s.Matches.Select(m => (m.Seed, m.Sides.Single())).ToArray());
    }

    [Fact]
    public void MoreTeamsRotateSoEveryEntrantPlaysEverySideOncePerSeed()
    {
        var s = new TournamentSchedule(teams: 3, entrants: 5, seeds: 2, firstSeed: 1);
        Assert.Equal(10, s.Matches.Count);
        foreach (var seed in s.Matches.GroupBy(m => m.Seed))
        {
            for (int t = 0; t < 3; t++)
            {
                Assert.Equal([0, 1, 2, 3, 4], seed.Select(m => m.Sides[t]).Order().ToArray());
            }

            Assert.All(seed, m => Assert.Equal(3, m.Sides.Distinct().Count()));
        }
    }

    [Fact]
    public void BadCountsAreRefused()
    {
        Assert.Throws<ArgumentException>(() => new TournamentSchedule(2, 1, 1, 1));
        Assert.Throws<ArgumentException>(() => new TournamentSchedule(1, 1, 0, 1));
        Assert.Throws<ArgumentException>(() => new TournamentSchedule(0, 3, 1, 1));
        Assert.Throws<ArgumentException>(() => new TournamentSchedule(2, 1000, 100, 1)); // 99.9 million matches
        Assert.Throws<ArgumentException>(() => new TournamentSchedule(1, 2, 2, long.MaxValue));
    }
}
