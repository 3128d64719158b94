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
        [("crowd 200", 3)] = "b11533624ab54e5d2b634b6abedf88b6ebfc7c01b62e804543e7f15c750f6b72",
        [("crowd 60", 1)] = "c8022ece53e216125925e4acd3df66e4329d9f60ea5ff41151d6cf0c1571a0f4",
        [("default", 1)] = "ad3bdd15db3839d4cd3e1c2a9d2f4b8db9a9cc8b7bec58802f38f0a12ae2b7ea",
        [("default", 2)] = "6df4044b13d632a18a1c6e09067dff2c37f46bf27aad5ac65f18b7ad7f5d86bd",
        [("item ball-grab", 1)] = "631726cea18bd3ab5afe1d67634e5e89e210194207ace381e128484b21ec0aba",
        [("item ball-grab", 2)] = "8a9ffef0bed8a33895ee1082c0b87e16729f0b49cc892d9034ef6fe0f30aee42",
        [("item ball-grab", 7)] = "7e9616a7ec80b2010de7c8cd3cec469c9f2d28d84c10ad8c6da52e1007bb23ee",
        [("item cross-country", 1)] = "a0b3273011ff1df4a0e40dd5ba28d095162365eab6800a91a7db747c252dcdcc",
        [("item cross-country", 2)] = "08b21b6a43971d3a09b758a2c725799f022cd3cb2fc56a83a8dc254f127c2a7e",
        [("item cross-country", 7)] = "28607835764b19a736a19c2a4141b0a526247abb6e29b66c3d2616fbdc6aac3a",
        [("item double-fish-race-via-holes", 1)] = "ce2048e3c54e6cbf55a1b8a5330fc7f2c4ce15f0b074704c9cbd851af4bf990b",
        [("item double-fish-race-via-holes", 2)] = "3aee536ae0e1108ddf590bf1bed4a3d2eff93d5a4a2d40129b62d893c7e0a0fd",
        [("item double-fish-race-via-holes", 7)] = "ff3f65c9fe8f2b66634eda3a6ab497aaa10b777a895384b2a136186e221831b5",
        [("item four-teams", 1)] = "6e8e0496ff087c62e6f7565631565715b8c0b62308b9a53bc8aaf2722a93cc3f",
        [("item four-teams", 2)] = "7d47f268570da84c08c6b40b3ddb3fb5ebff0c1ad8feaa381a49be7847262638",
        [("item four-teams", 7)] = "42540721184d7902e978a2ea22e6cde67bda5447410a537b709d1f84adccdbf1",
        [("item new-ball-grab", 1)] = "b6bcf7f27af8657d8e3bba02661daa5a0f65e67e54de32b3b6dba3b390491d0a",
        [("item new-ball-grab", 2)] = "88f6ef5e2f3ef5ec49a78782d41b98adfb9717f8461ac8a99345ef5f8ec6b52f",
        [("item new-ball-grab", 7)] = "eb12a301691c83c75d31a1b59ce313a23185da3fe2e9b5950dbd5201eb46c744",
        [("item polo-1v1", 1)] = "a3131dacd61e5d534bc60d1d34081c567e1a442c481f3db301d36d255cce027f",
        [("item polo-1v1", 2)] = "6feb904f088d81b60bcdc7c8a5e84b527fb8215ad18f5c2ccfc8a2cc259a2857",
        [("item polo-1v1", 7)] = "da3c97aea7e96751ad226eb1b93e609da1a400459d87b7716efbda85d25c1ed4",
        [("item polo-3v3", 1)] = "b98b9db332c54d9eac785166efb6d1398568a0efd7d8923e5cea047b47e79564",
        [("item polo-3v3", 2)] = "17ea844debbb0419a7b828a3e89532cd9d2048566f1c717caca8256357620294",
        [("item polo-3v3", 7)] = "425e0f9eaa0381e794f771e97482413e7c541f422bda1281828f3c12d49049e2",
        [("item polo-5v5", 1)] = "118ee37dd16f2e2824f9e5a9e48228507de091f928108645c30bc602ec96f47b",
        [("item polo-5v5", 2)] = "eaba04e3d84ddd689c7898212f20165dfbdf5274418070fee7a052c322cc3ce8",
        [("item polo-5v5", 7)] = "a5de99f72b7e7259560e9e831ba119c7e927a46c80fcac678dab212b1b4618d0",
        [("item rescue", 1)] = "56b2f3910e8fe6476187456fdd4e0756cc44dce5289ccfcae2f4d3af834d6857",
        [("item rescue", 2)] = "666698f9dd3d8577182333d72fefbc63bd2701b7379a515bb0bde08290f02659",
        [("item rescue", 7)] = "60a7b5846d2ec85d0c75f14dda8056e90e227e3f2563caef18fd9f22f46e1a62",
        [("item snooker", 1)] = "41d4ec1dfbfaf884a179bd6019444fe72be1b0cfa2a3e4d8b4360481f2ec7730",
        [("item snooker", 2)] = "0248b81fc3d670438a5651083e5a04f5d2d682d2ca738b062d0cb8a087d2bc5a",
        [("item snooker", 7)] = "02126c17483a87640d5bf97b6f5649a21f35b8af0359b2d8f9c2dcd2ff31328b",
        [("item survival", 1)] = "3d2a49d424ca7859d78bf1154de8d1d365f9c92489c426f21e6c04c12fde98b6",
        [("item survival", 2)] = "2a567d463125a0b4ccc5d4a85e9201c142c8d53793830012a59243d7053e68b0",
        [("item survival", 7)] = "1bc1007618298c333961d202fb8d21c959d1d85c2f1549b05d4c5216b197e53b",
        [("item synchronised-swimming", 1)] = "e2e6f74a483c04a025509f8f64ab5ba36eae9887ee2900e4b99584303112d8a6",
        [("item push-ball-avoid-obstacles", 1)] = "bc01a52df318d6a3eaabb0886c950047d5f0ed32f60f3848db9dc094fa9e62e0",
        [("item push-ball-avoid-obstacles", 2)] = "e26282f37de0be2ab093dcb57535fa67f8e25ea2f1ca638dd01840411669ee77",
        [("item push-ball-avoid-obstacles", 7)] = "677dae86bff717e5282ab793c78904b6fc2387e304de97f3ac44ff23daac2b7b",
        [("item push-ball-via-channel", 1)] = "59aa6c7a77551fe84362270602ed1ad144e4bf492ad199d101ca0ce9563d92cf",
        [("item push-ball-via-channel", 2)] = "8f8fa5700a86686ce84f4a3fc37a163245c90426f709dfc47f5483382ad14ddf",
        [("item push-ball-via-channel", 7)] = "3f3eeb989aeed765eece129a65888dd7ffa4f750104c13694663e2a30cca8d7b",
        [("item relay-with-ball", 1)] = "e0d60141fd2e62c1752a29b750efddbea1f777e9e89b789a597919f9c4d50724",
        [("item relay-with-ball", 2)] = "dbb6fc863d71f600d2ac2f0e7fdc7f28131c803e3602828113b81843f4d243c6",
        [("item relay-with-ball", 7)] = "5d724efaf96c09818a9d867b79946526077dab86d13054ab052c154e292c8d66",
        [("item synchronised-swimming", 2)] = "9377d588b1829b03f3a2ef23c7ffa4491533f5a72142160f0d4eb86fac872b14",
        [("item synchronised-swimming", 7)] = "989095ca2b1a98eae04a75fc5d24095da6372aea21559ccea5700e2f76fba625",
        [("item transport", 1)] = "d3392e9d40e13ed73222d9b6b2d06f9408dc1f3a69fa10520f47c7d7b807d6b4",
        [("item transport", 2)] = "3d3faa970ff4d0f7057435894fb657ddc42cd56f8576076677d7ce56c1036479",
        [("item transport", 7)] = "574733bc3f8769e7991a609dbf4c75a9f31176c7a2fc43d5d1f9e76daf62c95f",
    };

    // Whole matches: (scene, seed) → digest of a 6,000-cycle trace.
    private static readonly Dictionary<(string Scene, ulong Seed), string> PinnedLong = new()
    {
        [("default", 1)] = "3ff3341e3b67f700884efc8dfc37b47b8f6680a6dce6a2866c7dc9d657e6462c",
        [("item ball-grab", 1)] = "5e28f86182c26d63ea5079fe976703b0e1daca85d7901958971e3cd8c69d797c",
        [("item polo-3v3", 2)] = "7b8a6591cc2aaabc6ab31c75a7c49524cd3cba9270500a0e7ac2337cc0e752d2",
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
