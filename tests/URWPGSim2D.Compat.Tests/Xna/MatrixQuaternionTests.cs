using Microsoft.Xna.Framework;
using N = System.Numerics;

namespace URWPGSim2D.Compat.Tests.Xna;

/// <summary>XNA's Matrix, Quaternion and the vector transforms against hand-computed values, cross-checked with System.Numerics.</summary>
public sealed class MatrixQuaternionTests
{
    private const float Quarter = MathF.PI / 2f;

    [Fact]
    public void TranslationScaleAndTheAxisRotationsMoveTheUnitVectorsAsXnaDoes()
    {
        Assert.Equal(new Vector3(11f, 22f, 33f), Vector3.Transform(new Vector3(1f, 2f, 3f), Matrix.CreateTranslation(10f, 20f, 30f)));
        Assert.Equal(new Vector3(1f, 2f, 3f), Vector3.TransformNormal(new Vector3(1f, 2f, 3f), Matrix.CreateTranslation(10f, 20f, 30f)));
        Assert.Equal(new Vector3(2f, 6f, 12f), Vector3.Transform(new Vector3(1f, 2f, 3f), Matrix.CreateScale(2f, 3f, 4f)));
        Assert.Equal(new Vector3(-2f, -4f, -6f), Vector3.Transform(new Vector3(1f, 2f, 3f), Matrix.CreateScale(-2f)));
        Assert.Equal(Matrix.CreateScale(2f, 3f, 4f), Matrix.CreateScale(new Vector3(2f, 3f, 4f)));
        Assert.Equal(Matrix.CreateTranslation(1f, 2f, 3f), Matrix.CreateTranslation(new Vector3(1f, 2f, 3f)));
        // Right-handed, counter-clockwise looking down each axis: X → Y about Z, Y → Z about X, Z → X about Y (so X → −Z).
        Close(Vector3.UnitY, Vector3.Transform(Vector3.UnitX, Matrix.CreateRotationZ(Quarter)));
        Close(Vector3.UnitZ, Vector3.Transform(Vector3.UnitY, Matrix.CreateRotationX(Quarter)));
        Close(Vector3.UnitX, Vector3.Transform(Vector3.UnitZ, Matrix.CreateRotationY(Quarter)));
        Close(new Vector3(0f, 0f, -1f), Vector3.Transform(Vector3.UnitX, Matrix.CreateRotationY(Quarter)));
        // Row vectors: v·S·T scales first, then translates.
        Assert.Equal(new Vector3(12f, 20f, 30f), Vector3.Transform(Vector3.UnitX, Matrix.CreateScale(2f) * Matrix.CreateTranslation(10f, 20f, 30f)));
        Assert.Equal(new Vector3(22f, 40f, 60f), Vector3.Transform(Vector3.UnitX, Matrix.CreateTranslation(10f, 20f, 30f) * Matrix.CreateScale(2f)));
    }

    [Fact]
    public void TheNamedRowsAreXnas()
    {
        var m = Matrix.Identity;
        Assert.Equal((Vector3.UnitX, -Vector3.UnitX, Vector3.UnitY, -Vector3.UnitY), (m.Right, m.Left, m.Up, m.Down));
        Assert.Equal((new Vector3(0f, 0f, -1f), Vector3.UnitZ, Vector3.Zero), (m.Forward, m.Backward, m.Translation));
        m.Translation = new Vector3(4f, 5f, 6f);
        Assert.Equal((4f, 5f, 6f), (m.M41, m.M42, m.M43));
        m.Forward = new Vector3(0f, 0f, -2f);
        Assert.Equal(2f, m.M33);
        m.Down = new Vector3(0f, -3f, 0f);
        m.Left = new Vector3(-7f, 0f, 0f);
        Assert.Equal((3f, 7f), (m.M22, m.M11));
        m.Up = new Vector3(1f, 2f, 3f);
        m.Right = new Vector3(4f, 5f, 6f);
        m.Backward = new Vector3(7f, 8f, 9f);
        Assert.Equal(new Matrix(4f, 5f, 6f, 0f, 1f, 2f, 3f, 0f, 7f, 8f, 9f, 0f, 4f, 5f, 6f, 1f), m);
    }

    [Fact]
    public void ProductInverseDeterminantAndTransposeMatchHandValuesAndSystemNumerics()
    {
        var a = new Matrix(1f, 2f, 0f, 0f, 0f, 1f, 0f, 0f, 0f, 0f, 1f, 0f, 3f, 0f, 0f, 1f);
        var b = new Matrix(2f, 0f, 0f, 0f, 0f, 3f, 0f, 0f, 0f, 0f, 4f, 0f, 0f, 1f, 0f, 1f);
        // Row 1 of a·b: (1·2, 2·3, 0, 0); row 4: (3·2, 0 + 1, 0, 1).
        var ab = a * b;
        Assert.Equal((2f, 6f, 0f, 0f), (ab.M11, ab.M12, ab.M13, ab.M14));
        Assert.Equal((6f, 1f, 0f, 1f), (ab.M41, ab.M42, ab.M43, ab.M44));
        Assert.Equal((Matrix)N.Matrix4x4.Multiply(a, b), ab);
        Assert.Equal(ab, Matrix.Multiply(a, b));
        Assert.Equal(24f, Matrix.CreateScale(2f, 3f, 4f).Determinant());
        Assert.Equal(((N.Matrix4x4)ab).GetDeterminant(), ab.Determinant(), 4);
        var inverse = Matrix.Invert(ab);
        CloseM(Matrix.Identity, ab * inverse);
        Assert.True(float.IsNaN(Matrix.Invert(Matrix.CreateScale(0f)).M11));
        var t = Matrix.Transpose(a);
        Assert.Equal((2f, 3f), (t.M21, t.M14));
        Assert.Equal(a, Matrix.Transpose(t));
    }

    [Fact]
    public void EntryWiseArithmeticAndTheQuaternionTransform()
    {
        var a = new Matrix(1f, 2f, 3f, 4f, 5f, 6f, 7f, 8f, 9f, 10f, 11f, 12f, 13f, 14f, 15f, 16f);
        var b = Matrix.CreateScale(2f) + Matrix.Identity;
        Assert.Equal(32f, (a + a).M44);
        Assert.Equal(Matrix.CreateScale(2f), b - Matrix.Identity);
        Assert.Equal(-1f, (-a).M11);
        Assert.Equal(2f * a, a * 2f);
        Assert.Equal(0.5f, (a / 2f).M11);
        Assert.Equal(a * 0.5f, a / new Matrix(2f, 2f, 2f, 2f, 2f, 2f, 2f, 2f, 2f, 2f, 2f, 2f, 2f, 2f, 2f, 2f));
        Assert.Equal(8f, (a / b).M44); // entry by entry: 16 / 2 (b is diag(3, 3, 3, 2))
        Assert.Equal(1f + ((3f - 1f) * 0.25f), Matrix.Lerp(a, b, 0.25f).M11);
        Assert.Equal(2f * 0.75f, Matrix.Lerp(a, b, 0.25f).M12);
        Assert.True(a != b && a == new Matrix(1f, 2f, 3f, 4f, 5f, 6f, 7f, 8f, 9f, 10f, 11f, 12f, 13f, 14f, 15f, 16f));
        var q = Quaternion.CreateFromAxisAngle(Vector3.UnitY, 0.3f);
        Assert.Equal(a * Matrix.CreateFromQuaternion(q), Matrix.Transform(a, q));
    }

    [Fact]
    public void RotationsFromAnAxisAQuaternionOrYawPitchRollAgree()
    {
        CloseM(Matrix.CreateRotationY(0.7f), Matrix.CreateFromAxisAngle(Vector3.UnitY, 0.7f));
        CloseM(Matrix.CreateRotationZ(-1.1f), Matrix.CreateFromQuaternion(Quaternion.CreateFromAxisAngle(Vector3.UnitZ, -1.1f)));
        // Roll about Z first, then pitch about X, then yaw about Y.
        CloseM(Matrix.CreateRotationZ(0.3f) * Matrix.CreateRotationX(-0.4f) * Matrix.CreateRotationY(1.2f), Matrix.CreateFromYawPitchRoll(1.2f, -0.4f, 0.3f));
        var axis = Vector3.Normalize(new Vector3(1f, 2f, -2f));
        Matrix.CreateFromAxisAngle(ref axis, 0.9f, out var viaRef);
        CloseM((Matrix)N.Matrix4x4.CreateFromAxisAngle(axis, 0.9f), viaRef);
        Matrix.CreateFromYawPitchRoll(1.2f, -0.4f, 0.3f, out viaRef);
        CloseM(Matrix.CreateFromYawPitchRoll(1.2f, -0.4f, 0.3f), viaRef);
        var q = Quaternion.CreateFromYawPitchRoll(1.2f, -0.4f, 0.3f);
        Matrix.CreateFromQuaternion(ref q, out viaRef);
        CloseM(Matrix.CreateFromYawPitchRoll(1.2f, -0.4f, 0.3f), viaRef);
        Matrix.CreateRotationX(0.5f, out viaRef);
        Assert.Equal(Matrix.CreateRotationX(0.5f), viaRef);
        Matrix.CreateRotationY(0.5f, out viaRef);
        Assert.Equal(Matrix.CreateRotationY(0.5f), viaRef);
        Matrix.CreateRotationZ(0.5f, out viaRef);
        Assert.Equal(Matrix.CreateRotationZ(0.5f), viaRef);
    }

    [Fact]
    public void DecomposeRecoversScaleRotationAndTranslation()
    {
        var rotation = Quaternion.CreateFromAxisAngle(Vector3.UnitY, 0.6f);
        var m = Matrix.CreateScale(2f, 3f, 4f) * Matrix.CreateFromQuaternion(rotation) * Matrix.CreateTranslation(5f, 6f, 7f);
        Assert.True(m.Decompose(out var scale, out var q, out var translation));
        Close(new Vector3(2f, 3f, 4f), scale);
        Close(new Vector3(5f, 6f, 7f), translation);
        Assert.Equal(1f, MathF.Abs(Quaternion.Dot(rotation, q)), 4);
    }

    [Fact]
    public void CameraAndProjectionMatricesAreRightHanded()
    {
        // The camera at +10 Z looking at the origin: the origin is 10 in front, at view Z = −10.
        var view = Matrix.CreateLookAt(new Vector3(0f, 0f, 10f), Vector3.Zero, Vector3.Up);
        Close(new Vector3(0f, 0f, -10f), Vector3.Transform(Vector3.Zero, view));
        Close(new Vector3(1f, 0f, -10f), Vector3.Transform(Vector3.UnitX, view));
        var world = Matrix.CreateWorld(new Vector3(1f, 2f, 3f), Vector3.Forward, Vector3.Up);
        CloseM(Matrix.CreateTranslation(1f, 2f, 3f), world);
        // Perspective: a point on the near plane maps to depth 0, one on the far plane to depth 1 (after dividing by w).
        var p = Matrix.CreatePerspectiveFieldOfView(Quarter, 1.5f, 1f, 100f);
        CloseM((Matrix)N.Matrix4x4.CreatePerspectiveFieldOfView(Quarter, 1.5f, 1f, 100f), p);
        Assert.Equal(0f, Depth(p, -1f), 5);
        Assert.Equal(1f, Depth(p, -100f), 4);
        Assert.Throws<ArgumentOutOfRangeException>(() => Matrix.CreatePerspectiveFieldOfView(MathF.PI, 1f, 1f, 2f));
        Assert.Throws<ArgumentOutOfRangeException>(() => Matrix.CreatePerspective(1f, 1f, 2f, 1f));
        Assert.Equal(0f, Depth(Matrix.CreatePerspective(2f, 2f, 1f, 10f), -1f), 5);
        Assert.Equal(1f, Depth(Matrix.CreatePerspectiveOffCenter(-1f, 1f, -1f, 1f, 1f, 10f), -10f), 4);
        // Orthographic: the view box maps to [−1, 1]² × [0, 1] without a divide.
        Close(new Vector3(1f, -1f, 1f), Vector3.Transform(new Vector3(2f, -1f, -10f), Matrix.CreateOrthographic(4f, 2f, 0f, 10f)));
        Close(new Vector3(-1f, 1f, 0f), Vector3.Transform(new Vector3(0f, 5f, 0f), Matrix.CreateOrthographicOffCenter(0f, 4f, 0f, 5f, 0f, 10f)));
        var eye = new Vector3(0f, 0f, 10f);
        var target = Vector3.Zero;
        var up = Vector3.Up;
        Matrix.CreateLookAt(ref eye, ref target, ref up, out var r);
        Assert.Equal(view, r);
        Matrix.CreatePerspectiveFieldOfView(Quarter, 1.5f, 1f, 100f, out r);
        Assert.Equal(p, r);
    }

    [Fact]
    public void QuaternionsRotateComposeAndInvert()
    {
        var quarterZ = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, Quarter);
        float h = MathF.Sqrt(0.5f);
        Assert.Equal(h, quarterZ.Z, 6);
        Assert.Equal(h, quarterZ.W, 6);
        Close(Vector3.UnitY, Vector3.Transform(Vector3.UnitX, quarterZ));
        var quarterX = Quaternion.CreateFromAxisAngle(Vector3.UnitX, Quarter);
        // q1·q2 applies q2 first: X about X stays X, then about Z becomes Y.
        Close(Vector3.UnitY, Vector3.Transform(Vector3.UnitX, quarterZ * quarterX));
        Close(Vector3.UnitZ, Vector3.Transform(Vector3.UnitX, quarterX * quarterZ));
        Assert.Equal(quarterX * quarterZ, Quaternion.Concatenate(quarterZ, quarterX));
        Assert.Equal((Quaternion)N.Quaternion.Multiply(quarterZ, quarterX), quarterZ * quarterX);
        CloseQ(Quaternion.Identity, Quaternion.Inverse(quarterZ) * quarterZ);
        CloseQ(quarterX, (quarterX * quarterZ) / quarterZ);
        var c = quarterZ;
        c.Conjugate();
        Assert.Equal(Quaternion.Conjugate(quarterZ), c);
        Assert.Equal(new Quaternion(0f, 0f, -h, h), c);
        var n = new Quaternion(0f, 3f, 0f, 4f);
        Assert.Equal(5f, n.Length());
        n.Normalize();
        Assert.Equal(new Quaternion(0f, 0.6f, 0f, 0.8f), n);
        Assert.Equal(0.8f, Quaternion.Dot(n, Quaternion.Identity));
        CloseQ(Quaternion.CreateFromAxisAngle(Vector3.UnitZ, Quarter / 2f), Quaternion.Slerp(Quaternion.Identity, quarterZ, 0.5f));
        CloseQ(Quaternion.CreateFromAxisAngle(Vector3.UnitZ, Quarter / 2f), Quaternion.Lerp(Quaternion.Identity, quarterZ, 0.5f));
        CloseQ(Quaternion.CreateFromAxisAngle(Vector3.UnitX, 0.8f), Quaternion.CreateFromRotationMatrix(Matrix.CreateRotationX(0.8f)));
        CloseQ((Quaternion)N.Quaternion.CreateFromYawPitchRoll(0.1f, 0.2f, 0.3f), Quaternion.CreateFromYawPitchRoll(0.1f, 0.2f, 0.3f));
        Assert.Equal(new Quaternion(1f, 2f, 3f, 4f), new Quaternion(new Vector3(1f, 2f, 3f), 4f));
        Assert.Equal(new Quaternion(2f, 4f, 6f, 8f), new Quaternion(1f, 2f, 3f, 4f) + new Quaternion(1f, 2f, 3f, 4f));
        Assert.Equal(Quaternion.Identity, new Quaternion(1f, 2f, 3f, 5f) - new Quaternion(1f, 2f, 3f, 4f));
        Assert.Equal(new Quaternion(-1f, -2f, -3f, -4f), -new Quaternion(1f, 2f, 3f, 4f));
        Assert.Equal(new Quaternion(2f, 4f, 6f, 8f), new Quaternion(1f, 2f, 3f, 4f) * 2f);
        Assert.True(quarterZ != quarterX && quarterZ == Quaternion.CreateFromAxisAngle(Vector3.UnitZ, Quarter));
        Assert.Equal("{X:0 Y:0 Z:0 W:1}", Quaternion.Identity.ToString());
    }

    [Fact]
    public void TwoComponentVectorsTransformInTheirPlane()
    {
        var m = Matrix.CreateRotationZ(Quarter) * Matrix.CreateTranslation(10f, 20f, 30f);
        Close2(new Vector2(10f, 21f), Vector2.Transform(Vector2.UnitX, m));
        Close2(Vector2.UnitY, Vector2.TransformNormal(Vector2.UnitX, m));
        Close2(Vector2.UnitY, Vector2.Transform(Vector2.UnitX, Quaternion.CreateFromAxisAngle(Vector3.UnitZ, Quarter)));
        // A rotation about X tilts (0, 1, 0) toward Z; the two-component result keeps X and Y only.
        Close2(new Vector2(0f, 0f), Vector2.Transform(Vector2.UnitY, Quaternion.CreateFromAxisAngle(Vector3.UnitX, Quarter)));
        var v = new Vector2(3f, 4f);
        var q = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, 0.3f);
        Vector2.Transform(ref v, ref m, out var r);
        Assert.Equal(Vector2.Transform(v, m), r);
        Vector2.TransformNormal(ref v, ref m, out r);
        Assert.Equal(Vector2.TransformNormal(v, m), r);
        Vector2.Transform(ref v, ref q, out r);
        Assert.Equal(Vector2.Transform(v, q), r);
        Assert.Equal((Vector2)N.Vector2.Transform(v, (N.Matrix4x4)m), Vector2.Transform(v, m));
    }

    [Fact]
    public void ArrayTransformsFillTheDestinationRange()
    {
        var m = Matrix.CreateTranslation(1f, 2f, 3f);
        var q = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, Quarter);
        Vector3[] source = [Vector3.UnitX, Vector3.UnitY, Vector3.UnitZ];
        var all = new Vector3[3];
        Vector3.Transform(source, ref m, all);
        Assert.Equal(new[] { new Vector3(2f, 2f, 3f), new Vector3(1f, 3f, 3f), new Vector3(1f, 2f, 4f) }, all);
        var part = new Vector3[4];
        Vector3.Transform(source, 1, ref m, part, 2, 2);
        Assert.Equal(new[] { Vector3.Zero, Vector3.Zero, new Vector3(1f, 3f, 3f), new Vector3(1f, 2f, 4f) }, part);
        Vector3.TransformNormal(source, ref m, all);
        Assert.Equal(source, all);
        Vector3.TransformNormal(source, 0, ref m, part, 0, 1);
        Assert.Equal(Vector3.UnitX, part[0]);
        Vector3.Transform(source, ref q, all);
        Close(Vector3.UnitY, all[0]);
        Close(-Vector3.UnitX, all[1]);
        Vector3.Transform(source, 2, ref q, part, 3, 1);
        Close(Vector3.UnitZ, part[3]);
        Assert.Throws<ArgumentException>(() => Vector3.Transform(source, ref m, new Vector3[2]));
        Assert.Throws<ArgumentException>(() => Vector3.Transform(source, 2, ref m, part, 0, 2));
        Assert.Throws<ArgumentNullException>(() => Vector3.TransformNormal(null!, ref m, all));

        Vector2[] flat = [Vector2.UnitX, Vector2.UnitY];
        var out2 = new Vector2[2];
        Vector2.Transform(flat, ref m, out2);
        Assert.Equal(new[] { new Vector2(2f, 2f), new Vector2(1f, 3f) }, out2);
        Vector2.Transform(flat, 1, ref m, out2, 0, 1);
        Assert.Equal(new Vector2(1f, 3f), out2[0]);
        Vector2.TransformNormal(flat, ref m, out2);
        Assert.Equal(flat, out2);
        Vector2.TransformNormal(flat, 0, ref m, out2, 1, 1);
        Assert.Equal(Vector2.UnitX, out2[1]);
        Vector2.Transform(flat, ref q, out2);
        Close2(Vector2.UnitY, out2[0]);
        Vector2.Transform(flat, 1, ref q, out2, 1, 1);
        Close2(-Vector2.UnitX, out2[1]);
        Assert.Throws<ArgumentException>(() => Vector2.Transform(flat, ref q, new Vector2[1]));
    }

    [Fact]
    public void TextIsXnasForm() => Assert.Equal(
        "{ {M11:1 M12:0 M13:0 M14:0} {M21:0 M22:1 M23:0 M24:0} {M31:0 M32:0 M33:1 M34:0} {M41:0 M42:0 M43:0 M44:1} }",
        Matrix.Identity.ToString());

    // Normalized depth z/w of the view-space point (0, 0, viewZ).
    private static float Depth(Matrix projection, float viewZ)
    {
        var p = new Vector3(0f, 0f, viewZ);
        float z = (p.Z * projection.M33) + projection.M43;
        float w = (p.Z * projection.M34) + projection.M44;
        return z / w;
    }

    private static void Close(Vector3 expected, Vector3 actual)
    {
        Assert.Equal(expected.X, actual.X, 4);
        Assert.Equal(expected.Y, actual.Y, 4);
        Assert.Equal(expected.Z, actual.Z, 4);
    }

    private static void Close2(Vector2 expected, Vector2 actual)
    {
        Assert.Equal(expected.X, actual.X, 4);
        Assert.Equal(expected.Y, actual.Y, 4);
    }

    private static void CloseQ(Quaternion expected, Quaternion actual)
    {
        Assert.Equal(expected.X, actual.X, 4);
        Assert.Equal(expected.Y, actual.Y, 4);
        Assert.Equal(expected.Z, actual.Z, 4);
        Assert.Equal(expected.W, actual.W, 4);
    }

    private static void CloseM(Matrix expected, Matrix actual)
    {
        N.Matrix4x4 e = expected, a = actual;
        for (int i = 0; i < 4; i++)
        {
            for (int j = 0; j < 4; j++)
            {
                Assert.Equal(e[i, j], a[i, j], 4);
            }
        }
    }
}
