using System;
using Xunit.Sdk;
using URWPGSim2D.Testing;

namespace URWPGSim2D.Testing;

/// <summary>
/// A failed assertion inside a loop over random cases, with the case that failed (its seed and
/// index) in front of the assertion's own message, so the failure can be reproduced. Loops over
/// random inputs wrap their body: <c>try { … } catch (XunitException e) { throw RandomCaseException.At(seed, i, e); }</c>.
/// </summary>
public sealed class RandomCaseException : XunitException
{
    private RandomCaseException(string message, Exception inner)
        : base(message, inner)
    {
    }

    /// <summary>The failure <paramref name="inner"/> of case <paramref name="index"/> of the cases drawn from <paramref name="seed"/>.</summary>
    public static RandomCaseException At(object seed, int index, Exception inner) =>
        new($"random case {index} (seed {seed}) failed: {inner.Message}", inner);
}
