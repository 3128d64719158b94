using System.Reflection;
using Microsoft.Xna.Framework;
using N = System.Numerics;

namespace URWPGSim2D.Compat.Tests.Xna;

/// <summary>
/// XNA's overload families, found by reflection so that none is left out: every <c>ref</c>/<c>out</c> form of
/// <see cref="Vector2"/>, <see cref="Vector3"/>, <see cref="Matrix"/> and <see cref="Quaternion"/> gives what its value
/// form gives, and every static of the vectors that System.Numerics has too (same name, same parameters) gives what
/// System.Numerics gives.
/// </summary>
public sealed class OverloadFamiliesTests
{
    private static readonly Dictionary<Type, object[]> Samples = new()
    {
        [typeof(float)] = [0.2f, 0.3f, 0.45f, 0.7f, 1.9f, 2.6f],
        // The second sample lies below the third in every component: a clamp's bounds do not cross.
        [typeof(Vector2)] = [new Vector2(1.5f, -2f), new Vector2(-4f, -0.5f), new Vector2(0.25f, 3f), new Vector2(2f, 1f)],
        [typeof(Vector3)] = [new Vector3(1.5f, -2f, 3f), new Vector3(-4f, -0.5f, -2f), new Vector3(0.25f, 3f, 2.5f), new Vector3(2f, 1f, 0.5f)],
        [typeof(Matrix)] =
        [
            Matrix.CreateRotationZ(0.4f) * Matrix.CreateTranslation(1f, 2f, 3f) * Matrix.CreateScale(2f),
            Matrix.CreateFromYawPitchRoll(0.1f, 0.2f, 0.3f) * Matrix.CreateScale(1.5f),
        ],
        [typeof(Quaternion)] = [Quaternion.CreateFromYawPitchRoll(0.1f, 0.2f, 0.3f), Quaternion.CreateFromAxisAngle(Vector3.UnitX, -0.7f)],
    };

    public static TheoryData<Type, string[]> RefFamilies => new()
    {
        { typeof(Vector2), ["Add", "Subtract", "Multiply", "Divide", "Negate", "Min", "Max", "Clamp", "Normalize", "Reflect", "Lerp", "Distance", "DistanceSquared", "Dot", "Barycentric", "CatmullRom", "Hermite", "SmoothStep", "Transform", "TransformNormal"] },
        { typeof(Vector3), ["Add", "Subtract", "Multiply", "Divide", "Negate", "Min", "Max", "Clamp", "Normalize", "Reflect", "Lerp", "Distance", "DistanceSquared", "Dot", "Cross", "Barycentric", "CatmullRom", "Hermite", "SmoothStep", "Transform", "TransformNormal"] },
        { typeof(Matrix), ["Add", "Subtract", "Multiply", "Divide", "Negate", "Lerp", "Transpose", "Invert", "Transform", "CreatePerspective", "CreatePerspectiveOffCenter", "CreateOrthographic", "CreateOrthographicOffCenter"] },
        { typeof(Quaternion), ["Add", "Subtract", "Multiply", "Divide", "Negate", "Concatenate", "Conjugate", "Inverse", "Normalize", "Slerp", "Lerp", "CreateFromAxisAngle", "CreateFromYawPitchRoll", "CreateFromRotationMatrix", "Dot"] },
    };

    [Theory]
    [MemberData(nameof(RefFamilies))]
    public void EveryRefFormGivesWhatItsValueFormGives(Type type, string[] expected)
    {
        var seen = new HashSet<string>();
        var lone = new List<string>();
        foreach (var refForm in type.GetMethods(BindingFlags.Public | BindingFlags.Static))
        {
            var parameters = refForm.GetParameters();
            if (parameters.Length == 0 || !parameters[^1].IsOut || refForm.ReturnType != typeof(void))
            {
                continue;
            }

            var inputs = parameters[..^1].Select(p => Plain(p.ParameterType)).ToArray();
            var valueForm = type.GetMethod(refForm.Name, BindingFlags.Public | BindingFlags.Static, inputs);
            if (valueForm is null || valueForm.ReturnType != Plain(parameters[^1].ParameterType))
            {
                lone.Add(refForm.ToString()!);
                continue;
            }

            object?[] args = Arguments(inputs);
            object?[] refArgs = [.. args, null];
            Assert.True(Outcome(() => valueForm.Invoke(null, args)) == Outcome(() => { refForm.Invoke(null, refArgs); return refArgs[^1]; }), $"{refForm} differs from {valueForm}");
            seen.Add(refForm.Name);
        }

        Assert.Empty(lone);
        Assert.All(expected, name => Assert.Contains(name, seen));
    }

    public static TheoryData<Type, Type, string[]> NumericsTwins => new()
    {
        { typeof(Vector2), typeof(N.Vector2), ["Add", "Subtract", "Multiply", "Divide", "Negate", "Min", "Max", "Clamp", "Normalize", "Reflect", "Lerp", "Distance", "DistanceSquared", "Dot"] },
        { typeof(Vector3), typeof(N.Vector3), ["Add", "Subtract", "Multiply", "Divide", "Negate", "Min", "Max", "Clamp", "Normalize", "Reflect", "Lerp", "Distance", "DistanceSquared", "Dot", "Cross"] },
    };

    [Theory]
    [MemberData(nameof(NumericsTwins))]
    public void TheVectorStaticsSystemNumericsAlsoHasGiveWhatItGives(Type type, Type twin, string[] expected)
    {
        var seen = new HashSet<string>();
        foreach (var method in type.GetMethods(BindingFlags.Public | BindingFlags.Static).Where(m => !m.IsSpecialName))
        {
            var inputs = method.GetParameters().Select(p => p.ParameterType).ToArray();
            if (!inputs.All(t => t == type || t == typeof(float)) || !(method.ReturnType == type || method.ReturnType == typeof(float)))
            {
                continue;
            }

            var numerics = twin.GetMethod(method.Name, BindingFlags.Public | BindingFlags.Static, inputs.Select(t => t == type ? twin : t).ToArray());
            if (numerics is null)
            {
                continue;
            }

            object?[] args = Arguments(inputs);
            float[] expectedValue = Components(numerics.Invoke(null, args.Select(a => a is float ? a : ToNumerics(a!)).ToArray())!);
            float[] actual = Components(method.Invoke(null, args)!);
            Assert.Equal(expectedValue.Length, actual.Length);
            for (int i = 0; i < actual.Length; i++)
            {
                Assert.True(MathF.Abs(expectedValue[i] - actual[i]) <= 1e-5f * MathF.Max(1f, MathF.Abs(expectedValue[i])), $"{method}: component {i} is {actual[i]}, System.Numerics gives {expectedValue[i]}");
            }

            seen.Add(method.Name);
        }

        Assert.All(expected, name => Assert.Contains(name, seen));
    }

    private static Type Plain(Type t) => t.IsByRef ? t.GetElementType()! : t;

    // The k-th parameter of a type gets that type's k-th sample (a nullable one its underlying type's).
    private static object?[] Arguments(Type[] inputs)
    {
        var used = new Dictionary<Type, int>();
        return inputs.Select(t =>
        {
            var kind = Nullable.GetUnderlyingType(t) ?? t;
            Assert.True(Samples.TryGetValue(kind, out var samples), $"no sample of {kind}");
            int k = used.GetValueOrDefault(kind);
            used[kind] = k + 1;
            return samples[k % samples.Length];
        }).ToArray();
    }

    // A result's components to the bit (NaN equals NaN), or the kind of exception thrown instead.
    private static string Outcome(Func<object?> call)
    {
        try
        {
            return string.Join(' ', Components(call()!).Select(f => BitConverter.SingleToInt32Bits(f).ToString("x8", System.Globalization.CultureInfo.InvariantCulture)));
        }
        catch (TargetInvocationException e)
        {
            return e.InnerException!.GetType().Name;
        }
    }

    private static object ToNumerics(object xna) => xna switch
    {
        Vector2 v => new N.Vector2(v.X, v.Y),
        Vector3 v => new N.Vector3(v.X, v.Y, v.Z),
        _ => throw new ArgumentException($"no System.Numerics twin of {xna.GetType()}", nameof(xna)),
    };

    private static float[] Components(object value) => value switch
    {
        float f => [f],
        Vector2 v => [v.X, v.Y],
        Vector3 v => [v.X, v.Y, v.Z],
        N.Vector2 v => [v.X, v.Y],
        N.Vector3 v => [v.X, v.Y, v.Z],
        Quaternion q => [q.X, q.Y, q.Z, q.W],
        Matrix m => [m.M11, m.M12, m.M13, m.M14, m.M21, m.M22, m.M23, m.M24, m.M31, m.M32, m.M33, m.M34, m.M41, m.M42, m.M43, m.M44],
        _ => throw new ArgumentException($"no components of {value.GetType()}", nameof(value)),
    };
}
