using System.Security.Cryptography;
using URWPGSim2D.Engine.Matches;
using URWPGSim2D.Engine.Trace;

namespace URWPGSim2D.Server.Tests.Trace;

/// <summary>
/// The safety net of every change that must not change a match: the SHA-256 of the whole trace
/// (the bytes <c>run --trace</c> writes: every cycle line and its newline) of every competition
/// item on its own layout with its demo strategies and noise on, for several seeds, of the default
/// scene and of crowds, pinned. A short match (a few hundred cycles) keeps the test cheap; an item's
/// halves, extra time and penalties scale with the cycles asked for, so a tied polo match plays them
/// here too. A refactoring that changes one byte of one trace fails here, naming the case and the
/// new digest; a deliberate change of the physics or of the trace format updates the table.
/// A few whole matches of 6,000 cycles are pinned too (a change of, say, the order of two
/// simultaneous contacts can take thousands of cycles to show). Every case, and one whole match, is
/// played again with the motion world's islands spread over two threads: the same bytes.
/// </summary>
public sealed class TraceDigestTests
{
    // Cycles a match is built for (an item's phases depend on it).
    private const int ItemCycles = 300;

    // (scene, seed) → digest of the trace. Scenes: "item SLUG", "default", "crowd N".
    private static readonly Dictionary<(string Scene, ulong Seed), string> Pinned = new()
    {
        [("crowd 200", 3)] = "01f5e1e76efe0a90bb5302a1ac8957f305a6d5775f3dd16b5093c7a0e2b8a12f",
        [("crowd 60", 1)] = "bb76286546c0a3707cba62ae27d232bbb3f601840a4fb3a811ced7c98f9b7f82",
        [("default", 1)] = "3dcb76c8150b37d3a1c86d60a893c1c23a9ce9f3bbad86376140ce88af568b87",
        [("default", 2)] = "157589c49bc998b2c0b43395d40e7752231f909a00888e051866517a2dc9ed9b",
        [("item ball-grab", 1)] = "a9ae7c026eaddc2fbde60b7750339da9e37f0977859d44961e568e912f2baac2",
        [("item ball-grab", 2)] = "7a6f7d3458c06beb09e0d9492eec7d5dcbd8560ca9568320edd5a8b9c13a8dec",
        [("item ball-grab", 7)] = "4142ac036466541b150b305c6d764d0c6a5babb9075b8a626b75c42e7af814d3",
        [("item cross-country", 1)] = "8d470e32e000205775f851ebcc5c793278b4ccf78b27dbf19a17b33c296752e3",
        [("item cross-country", 2)] = "494763d6c0631e69cff6e0419129820aa6e23d8e1b648d7128d8313a920006c0",
        [("item cross-country", 7)] = "0bb8f85b93b48beb61bf5e03b46a729a0637c813b832e7530c2cd7cdc1660aeb",
        [("item double-fish-race-via-holes", 1)] = "9353a5f1232635280d0de340c909ebe7f95ef0c34b858fa463f5bf8e997a439e",
        [("item double-fish-race-via-holes", 2)] = "83b89dec0f27c23b835222f39ed55a0e3f8deb48271ca2fcbc6e8e10660a4ad5",
        [("item double-fish-race-via-holes", 7)] = "1f606edf6135c8614a2d63c0219ffb23655c7a25b504805bb3cc5bc7f8c584d8",
        [("item four-teams", 1)] = "a98baed8ef73a3ae62be90cc712b766a4f23d88ed3c4d6fbf3e51d5a095ac493",
        [("item four-teams", 2)] = "e400fd5462e4d6fe9260b07d50090c179fe4e7721ae4110fd702a5ad6a5090ad",
        [("item four-teams", 7)] = "1784d5f795fb00fd1df689a0f829633cb1c7801039006a1b480042e60091a7cc",
        [("item new-ball-grab", 1)] = "d56a5ab4611320dfc3aac5bcd6bb0be39c57b7a3c005cb3fca6c942813cf8d96",
        [("item new-ball-grab", 2)] = "521f5abf1c921b5c37100298a12db3e9d118b83aa98206f757d342125668504d",
        [("item new-ball-grab", 7)] = "5b03a8bc62c24707c634e0962729373b110fd96f5f6cce16c06036ab038681ba",
        [("item polo-1v1", 1)] = "626df57165a8a4ce485d69241e7b94a372a9048ab276a7c5dd9d58c35e97858c",
        [("item polo-1v1", 2)] = "f1f12f93cf2c5f7b3a29a1832b876c6ceb4b95fc9ba5313935c1d085cdc4636a",
        [("item polo-1v1", 7)] = "a443b49a6ceaf8074b0499d82466a9580ebb4b48b5374c4f3c94a32d83454530",
        [("item polo-3v3", 1)] = "e6ae56984492d7d726a0237dc0e5039b0b7e8087f262629d0b38921a9123a00d",
        [("item polo-3v3", 2)] = "5aca48b68d8c4973d19207d142878d0cc1071dbe96eeb0036ed997b64582cb23",
        [("item polo-3v3", 7)] = "80726b9bcb7a30727693e309499128c35cbe95905ba2ba5907733ca6589351cf",
        [("item polo-5v5", 1)] = "051950b0921e0268a2e4982805bd5646db25392777739959308e9996ad3e88ec",
        [("item polo-5v5", 2)] = "b9baf886848051b5598224b6407cf0800c581c49c5215ee8d54adf09546fa8d7",
        [("item polo-5v5", 7)] = "f9cc0b78e8c27d30246f2526e201da468d00846944bb84f7343547c99bce997f",
        [("item rescue", 1)] = "75597149db9148dfca24456a5a9eb8198ee9c4231280b61dd6a4a8a3de94371c",
        [("item rescue", 2)] = "307c13e024241936541511046059ddc41e457eb696b86c13f61e5c16772c3acd",
        [("item rescue", 7)] = "520aa9a3d11855f8f729eb94a5b3ef8433a80f78218445dfae1c096547af122b",
        [("item snooker", 1)] = "a4d924a40dffd5a5b5177ea7806560da9b11d672eab8f86f951432f5ed956212",
        [("item snooker", 2)] = "9a3d69158b029a1656de9ac25849c89f4584634e63e6605e1deabc0a32dd0279",
        [("item snooker", 7)] = "7ee101215b5da7d9eac62390741b35f55c9491be3a9ad230cabee1350ee7ee3a",
        [("item survival", 1)] = "e56fc00ec288a0dda568a16566c4f9015004b287fe2943d4712128f267ceb007",
        [("item survival", 2)] = "e326335d85e634f847552302929c09d052d4d948a5d10bb5a1289e1c5113fe00",
        [("item survival", 7)] = "37ed74165f0ce8874dd3bfbf4dd25c8ed22f0b45bb813ec446f2e647e08cf87a",
        [("item synchronised-swimming", 1)] = "638ee1a36d43c36edfe4c3260cacfdd1bee1552474845981defc2aea88e638b3",
        [("item push-ball-avoid-obstacles", 1)] = "7ceeced94d1f7457857ced5e521cf64a902ddbd7f51c29eff9ff9173cddbe1e2",
        [("item push-ball-avoid-obstacles", 2)] = "e26282f37de0be2ab093dcb57535fa67f8e25ea2f1ca638dd01840411669ee77",
        [("item push-ball-avoid-obstacles", 7)] = "d196d266af81590e3f25e7a2544d18d5878ae42cfa21b26ec90a4545bed8dc8e",
        [("item push-ball-via-channel", 1)] = "ff3c102addb553cb4eae81d58f83b249875554a63800ec7aeae09203239ef7c7",
        [("item push-ball-via-channel", 2)] = "9f49e9624123de8609340eb1e4299c488ff161879aea5e9ef11dc10ed1af8bf1",
        [("item push-ball-via-channel", 7)] = "34aca29f5db1d5f641ad1d57a12a96fa24992e3eb798f796445749fef1d4e837",
        [("item relay-with-ball", 1)] = "c1490d5261f7c6e79d32c0f49f9529b7ee4dba325e61489d7341c8970c076182",
        [("item relay-with-ball", 2)] = "bfeb56078db25094aea9b7c5d970c57685ff6b85d4c79a343159869afaa1c895",
        [("item relay-with-ball", 7)] = "a584cf96552ff21d62517e0151c7475b9f017d0d8cdd48a272eeed3b9204ae11",
        [("item synchronised-swimming", 2)] = "3d9b9b9c80a29490cfa97b29ebb0616ab6c662695a6c37a31395e895f813e7bd",
        [("item synchronised-swimming", 7)] = "6139512222db0a09dc56bf9c7d3e35b1cc63394f844213dd32a1e72f31703bbe",
        [("item transport", 1)] = "695ad751969af1131a47a42491cf93cdb7d966bc4a6f07f73886c7955f0d8f46",
        [("item transport", 2)] = "3bc7e1ab74a813b8f067c1c115e2be01921047e3ff5ef1e2552052ca5cef3e06",
        [("item transport", 7)] = "e5958aea1c3951c5525a4b4160ba7e7486986ebe31faf078fee3e5b0708bd3b8",
    };

    // Whole matches: (scene, seed) → digest of a 6,000-cycle trace.
    private static readonly Dictionary<(string Scene, ulong Seed), string> PinnedLong = new()
    {
        [("default", 1)] = "8adb5c6e249832e4323fad6c1be58485cb3f3abc80c943aa80cdcb2521458156",
        [("item ball-grab", 1)] = "b98b53568aee67d7b91435635244252c62ee1af0c41324fd67c96b5b6bf2f478",
        [("item polo-3v3", 2)] = "1bbe615c27f9f77443ad808f272f42b737bb2751c4863edf75a06bc6ebb35c44",
    };

    private const int LongCycles = 6_000;

    private static readonly ulong[] Seeds = [1, 2, 7];

    /// <summary>The cases: every registered item × <see cref="Seeds"/>, the default scene and two crowds.</summary>
    public static TheoryData<string, ulong> Cases()
    {
        var cases = new TheoryData<string, ulong>();
        foreach (var item in ItemRegistry.All)
        {
            foreach (ulong seed in Seeds)
            {
                cases.Add("item " + item.Slug, seed);
            }
        }

        cases.Add("default", 1);
        cases.Add("default", 2);
        cases.Add("crowd 60", 1);
        cases.Add("crowd 200", 3);
        return cases;
    }

    [Theory]
    [MemberData(nameof(Cases))]
    public void TheTraceIsByteIdenticalToThePinnedOne(string scene, ulong seed)
    {
        string actual = Digest(scene, seed);
        Assert.True(Pinned.TryGetValue((scene, seed), out string? expected),
            $"no pinned digest for {scene} seed {seed}: add [(\"{scene}\", {seed})] = \"{actual}\", to the table (measured on the commit before your change)");
        Assert.True(expected == actual, $"{scene} seed {seed}: the trace changed: digest {actual}, pinned {expected}");
    }

    [Theory]
    [InlineData("default", 1UL)]
    [InlineData("item ball-grab", 1UL)]
    [InlineData("item polo-3v3", 2UL)]
    public void AWholeMatchIsByteIdenticalToThePinnedOne(string scene, ulong seed)
    {
        string actual = Digest(scene, seed, LongCycles);
        Assert.True(PinnedLong.TryGetValue((scene, seed), out string? expected), $"no pinned digest for {scene} seed {seed} ({LongCycles} cycles): {actual}");
        Assert.True(expected == actual, $"{scene} seed {seed}, {LongCycles} cycles: the trace changed: digest {actual}, pinned {expected}");
    }

    [Theory]
    [MemberData(nameof(Cases))]
    public void OnTwoThreadsEveryTraceIsThePinnedOne(string scene, ulong seed)
    {
        string actual = Digest(scene, seed, threads: 2);
        Assert.True(Pinned[(scene, seed)] == actual, $"{scene} seed {seed} on two threads: digest {actual}, pinned {Pinned[(scene, seed)]}");
    }

    [Fact]
    public void OnTwoThreadsAWholeMatchIsThePinnedOne()
    {
        string actual = Digest("item ball-grab", 1, LongCycles, threads: 2);
        Assert.True(PinnedLong[("item ball-grab", 1)] == actual, $"item ball-grab seed 1, {LongCycles} cycles on two threads: digest {actual}");
    }

    [Fact]
    public void EveryPinnedCaseIsStillPlayed()
    {
        var played = Cases().Select(c => ((string)c[0], (ulong)c[1])).ToHashSet();
        foreach (var key in Pinned.Keys)
        {
            Assert.Contains(key, played);
        }
    }

    [Fact]
    public void ADifferentSeedGivesADifferentTrace()
    {
        // The digest sees the match: the seed changes the noise, so the trace.
        Assert.NotEqual(Digest("item ball-grab", 1), Digest("item ball-grab", 2));
    }

    // The digest of the trace of a scene played as `run` plays it (the one match loop), for the
    // scene's own cycles unless others are given; on two threads, every world's islands are spread.
    private static string Digest(string scene, ulong seed, int cycles = 0, int threads = 1)
    {
        var (scenario, sceneCycles) = Scene(scene, seed);
        cycles = cycles > 0 ? cycles : sceneCycles;
        using var hash = new TraceHash();
        Match match = new MatchSettings(scenario, cycles, seed, Threads: threads).Build();
        if (threads > 1)
        {
            match.Motion.MinimumMoversForThreads = 2;
        }

        using var loop = new MatchLoop(match, cycles, hash);
        loop.Play();
        return hash.Digest();
    }

    // SHA-256 of the lines and their newlines.
    private sealed class TraceHash : ITraceSink, IDisposable
    {
        private readonly IncrementalHash _hash = IncrementalHash.CreateHash(HashAlgorithmName.SHA256);

        public void WriteLine(ReadOnlySpan<byte> line)
        {
            _hash.AppendData(line);
            _hash.AppendData("\n"u8);
        }

        public string Digest() => Convert.ToHexStringLower(_hash.GetHashAndReset());

        public void Dispose() => _hash.Dispose();
    }

    private static (ScenarioDefinition Scenario, int Cycles) Scene(string scene, ulong seed)
    {
        if (scene.StartsWith("item ", StringComparison.Ordinal))
        {
            return (ItemRegistry.Find(scene[5..])!.CreateScenario(seed), ItemCycles);
        }

        if (scene == "default")
        {
            return (DefaultScenario.Load(), 200);
        }

        int movers = int.Parse(scene.AsSpan(6), CultureInfo.InvariantCulture);
        return (CrowdScenario.Create(movers, seed), 100);
    }
}
