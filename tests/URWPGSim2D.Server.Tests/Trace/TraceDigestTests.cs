using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;
using System.Security.Cryptography;
using URWPGSim2D.Server.Items;
using URWPGSim2D.Server.Scenario;
using URWPGSim2D.Server.Simulation;
using URWPGSim2D.Server.Trace;
using Xunit;

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
/// simultaneous contacts can take thousands of cycles to show), and some cases are played again
/// with the stepper's islands spread over two threads: the same bytes.
/// </summary>
public sealed class TraceDigestTests
{
    // Cycles a match is built for (an item's phases depend on it).
    private const int ItemCycles = 300;

    // (scene, seed) → digest of the trace. Scenes: "item SLUG", "default", "crowd N".
    private static readonly Dictionary<(string Scene, ulong Seed), string> Pinned = new()
    {
        [("crowd 200", 3)] = "f6291e3664e38c76f57402835f5087951ccaab7836bc652410c7b6a46ab236b1",
        [("crowd 60", 1)] = "8b0d02fb4fc274512c57830730386054e2a9409b981e266c956a2c8a7f5864ba",
        [("default", 1)] = "0e5f1652275defbeb692a2be6dc7ae9980cf17fef5f36b70e3b9f0fa111a6f2f",
        [("default", 2)] = "d294556a3d184f15b8ed12a1f53bdd1426150ac5c1dfc52e943f966263d3f9a9",
        [("item ball-grab", 1)] = "9e48e130f80e050e3a08a3d6620e9d7f0947b399c65eef4725222156346c701c",
        [("item ball-grab", 2)] = "ac6817164cf5fcfbab9bf6d34dd5d93260fe980e9c9228f6347f9337438b2003",
        [("item ball-grab", 7)] = "bd0f71c191e09fcc0293fbd420f2ce039225217c4ba4deb018cb1cfde4adf348",
        [("item cross-country", 1)] = "d19c9b74efc0a79864005d355f86d93556e0690c76329f7467d3bf7a1baecb33",
        [("item cross-country", 2)] = "3207b7543b027c7d27342f7e1fc0d607c39926ff7606cde9f81a905ab031755e",
        [("item cross-country", 7)] = "15c3a0dcc0ec5ca266fd1c4d379838b87506ef91920784b1b7ab975babfa8b90",
        [("item double-fish-race-via-holes", 1)] = "6214635b396ddd1f9df7480d479214ec5ecb81837f9b0c20dac2d401d3756002",
        [("item double-fish-race-via-holes", 2)] = "698b06ab668644e5b9549453353564ec72a14f2f0d8b0e977d9b20ea979aff21",
        [("item double-fish-race-via-holes", 7)] = "e9de89577944518aeb7a7ce84c1b7b1f9b9af04fe9a7e83d1f443f8d457af07e",
        [("item four-teams", 1)] = "6eb970c859e4350ac2d20d9adf5d09a5ec84d31463a72a8c736370095f136f9a",
        [("item four-teams", 2)] = "cd49c57579b81d2bb21df6d0e6d834e4d3278a7cbb15407c2c9e31b1163131aa",
        [("item four-teams", 7)] = "e660fe1f5c90b0ae1c626435d3f841bc5f90c99762ac374f8ee82b91ca4907f4",
        [("item new-ball-grab", 1)] = "654b43d80e39935e6dd97549ac247073c90c690c991f7a7535c29e5517a4319b",
        [("item new-ball-grab", 2)] = "6b56da7092acc3c16dfc15216b65c9e752d9a2b84a72be0f3fe58c1c6e9fb13c",
        [("item new-ball-grab", 7)] = "583fcb6fcd08dbe1359ec916dacb0abf75285de42c572282765d76535caa1e27",
        [("item polo-1v1", 1)] = "264e89d23a09cda5ce49cdeae7b11b3275d9470457cf523d081f877f13bd9268",
        [("item polo-1v1", 2)] = "d16dae27adc72341204d7ad96b48315d8f68f7384954da4a68f3b83d26b40fc4",
        [("item polo-1v1", 7)] = "df941268b3fee7ad7db7daa12a50c5063957092f92bdfcbd3e85e0f445652f7b",
        [("item polo-3v3", 1)] = "bd2b29260e279225545ac759c45e73616e5012b0b388f86347ca36b54db1db45",
        [("item polo-3v3", 2)] = "6f34103a73b6d6a853ce918f53122e1053f27cf8ffd2ab4a04063582c37a5898",
        [("item polo-3v3", 7)] = "33beef61f160bb75a7498151707e719b3e243d2d375917645e52f5a4162a0382",
        [("item polo-5v5", 1)] = "c2bce5af6f3367e020c9778884fda4e310d057a9ffa15e1788fd67ac162e7e57",
        [("item polo-5v5", 2)] = "afab2112d97a357cbee969e194c71736d4a2cde48dfa167bb96a2cbb94420217",
        [("item polo-5v5", 7)] = "52a033789055996c3ad0a4bfddee2622f25363feb2126a4d18a73b59756ff50d",
        [("item rescue", 1)] = "b6fd767dd83f69cde1ea1fbb797e91c6ca812f259a936429f6eb4f9ac6e205f8",
        [("item rescue", 2)] = "629247f791bda562db1cd74d16eddccb16e347610104fd0d83fb7752381d99be",
        [("item rescue", 7)] = "9ec61656aa344e159743b35e093a4fc7d874df1e889980faea13f67404b395b8",
        [("item snooker", 1)] = "a53d0c522c2000e24118c9b9b1af3ad11a470de20c1dcf6e98813ecb7748de0d",
        [("item snooker", 2)] = "c849c2fae8938ce63f54fe296980dbf1496b6d37d9708dd93e4c375c00b1cd6e",
        [("item snooker", 7)] = "43d7ad8d4dd0cdf2074aca70697fba3141c2aa1afc2d7ebe0d129db42c8a7561",
        [("item survival", 1)] = "3f1caf86ea0356216a05fc8546fa4e538628ce39df0e02e1535832a18978c995",
        [("item survival", 2)] = "52d612c123c653f8a15d51a34528c41f9dc047edc907fba666a205db39dc1012",
        [("item survival", 7)] = "d48630166e5f5e9b2161fbcdfdd3244ff9ec2f7794a799ffd4c2b0bbc324fda6",
        [("item synchronised-swimming", 1)] = "91b2f28b063b97fe8c21ccd6bf56733472d380e0aff7014cd16df4af6800a956",
        [("item push-ball-avoid-obstacles", 1)] = "398fa68494383178f07f523c8d68bab68cfafbd587467c9abcb2e011e1cba26d",
        [("item push-ball-avoid-obstacles", 2)] = "280173cf727602ed471d1b7cabfe55e66fe9f95091623acc90345c6199772d85",
        [("item push-ball-avoid-obstacles", 7)] = "3629981b0d4605cc45c314201a97dd688a679c412137630a25b76a63f2bdeed0",
        [("item push-ball-via-channel", 1)] = "b4236659b73cea5149eef1bf95984dd40e65253fea902227a1ce87d0f3271919",
        [("item push-ball-via-channel", 2)] = "c27b095e688ee20c8965c05c429efc7bf0162595a107335e0b6696e146fd4853",
        [("item push-ball-via-channel", 7)] = "2ef337d5ce9d59fd8aa8104fc4cb343946f00723d745d1a2952ae78a8c1fc239",
        [("item relay-with-ball", 1)] = "2a75960d64829ac410526931dccf5669583dcdc11fb6f7ed19c6b57edd693523",
        [("item relay-with-ball", 2)] = "c6265446e54f23782f4d40a2adbbf4d4949ad82c55bb14043634b6226105df04",
        [("item relay-with-ball", 7)] = "dcf2b8a1d92bd9822778ddb9eb3b6619df418bcc82db19fe6b73d42e097aa5be",
        [("item synchronised-swimming", 2)] = "a1b4db8c83d24a98e7a56dfd9a8b12e8b4e569899134c7256d828ff9d4ad763d",
        [("item synchronised-swimming", 7)] = "768f0e400ea37ca8f1e58ab213d23881057ee197736623703762efaa6f6b5004",
        [("item transport", 1)] = "093714c5373cef4efc7751ab33fa906a53c693a8937abc99ce8f765c88ff8d91",
        [("item transport", 2)] = "c32a39091e5eb8f3873b7a00026ad5e11ed52723260c8ad8e0ccec5e2fdb7a78",
        [("item transport", 7)] = "d12982f2a098f60535567b58e00a95e1884e0cad20bce933d89dff86e48d50d0",
    };

    // Whole matches: (scene, seed) → digest of a 6,000-cycle trace.
    private static readonly Dictionary<(string Scene, ulong Seed), string> PinnedLong = new()
    {
        [("default", 1)] = "2ba75716a8dd8690d15276d9d303bd90b0472a6d19ba438b14dcdc7fb8b8eafa",
        [("item ball-grab", 1)] = "6d6fbd1c91741f87abc7401ad2b896b48ba2917ed98ce0fa870f551984cc7cf7",
        [("item polo-3v3", 2)] = "e5ae9048b843ba65dc24977f6d3ee29ad1b3d657c281f11a659e28fa10a99221",
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
    [InlineData("crowd 200", 3UL, 0)]
    [InlineData("item polo-5v5", 1UL, 0)]
    [InlineData("item ball-grab", 1UL, LongCycles)]
    public void OnTwoThreadsTheTraceIsThePinnedOne(string scene, ulong seed, int cycles)
    {
        string actual = Digest(scene, seed, cycles, threads: 2);
        string expected = cycles == 0 ? Pinned[(scene, seed)] : PinnedLong[(scene, seed)];
        Assert.True(expected == actual, $"{scene} seed {seed} on two threads: digest {actual}, pinned {expected}");
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
            match.Stepper.MinimumMoversForThreads = 2;
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
