using System.Globalization;
using N = System.Numerics;

namespace Microsoft.Xna.Framework;

/// <summary>
/// XNA 3.1's 4×4 matrix: a mutable struct with public fields M11…M44, for row vectors (a point transforms as
/// v·M, the translation is in M41…M43), right-handed, as <see cref="System.Numerics.Matrix4x4"/> (same layout
/// and conventions; the two convert implicitly). XNA's billboard, shadow and reflection constructors (which need its
/// <c>Plane</c> and nullable vectors) are not offered.
/// </summary>
[Serializable]
public struct Matrix : IEquatable<Matrix>
{
    /// <summary>Row 1, column 1.</summary>
    public float M11;

    /// <summary>Row 1, column 2.</summary>
    public float M12;

    /// <summary>Row 1, column 3.</summary>
    public float M13;

    /// <summary>Row 1, column 4.</summary>
    public float M14;

    /// <summary>Row 2, column 1.</summary>
    public float M21;

    /// <summary>Row 2, column 2.</summary>
    public float M22;

    /// <summary>Row 2, column 3.</summary>
    public float M23;

    /// <summary>Row 2, column 4.</summary>
    public float M24;

    /// <summary>Row 3, column 1.</summary>
    public float M31;

    /// <summary>Row 3, column 2.</summary>
    public float M32;

    /// <summary>Row 3, column 3.</summary>
    public float M33;

    /// <summary>Row 3, column 4.</summary>
    public float M34;

    /// <summary>Row 4, column 1.</summary>
    public float M41;

    /// <summary>Row 4, column 2.</summary>
    public float M42;

    /// <summary>Row 4, column 3.</summary>
    public float M43;

    /// <summary>Row 4, column 4.</summary>
    public float M44;

    /// <summary>Creates a matrix from its sixteen entries, row by row.</summary>
    /// <param name="m11">Row 1, column 1.</param>
    /// <param name="m12">Row 1, column 2.</param>
    /// <param name="m13">Row 1, column 3.</param>
    /// <param name="m14">Row 1, column 4.</param>
    /// <param name="m21">Row 2, column 1.</param>
    /// <param name="m22">Row 2, column 2.</param>
    /// <param name="m23">Row 2, column 3.</param>
    /// <param name="m24">Row 2, column 4.</param>
    /// <param name="m31">Row 3, column 1.</param>
    /// <param name="m32">Row 3, column 2.</param>
    /// <param name="m33">Row 3, column 3.</param>
    /// <param name="m34">Row 3, column 4.</param>
    /// <param name="m41">Row 4, column 1.</param>
    /// <param name="m42">Row 4, column 2.</param>
    /// <param name="m43">Row 4, column 3.</param>
    /// <param name="m44">Row 4, column 4.</param>
    public Matrix(float m11, float m12, float m13, float m14, float m21, float m22, float m23, float m24, float m31, float m32, float m33, float m34, float m41, float m42, float m43, float m44)
    {
        M11 = m11;
        M12 = m12;
        M13 = m13;
        M14 = m14;
        M21 = m21;
        M22 = m22;
        M23 = m23;
        M24 = m24;
        M31 = m31;
        M32 = m32;
        M33 = m33;
        M34 = m34;
        M41 = m41;
        M42 = m42;
        M43 = m43;
        M44 = m44;
    }

    /// <summary>The identity matrix.</summary>
    public static Matrix Identity => new(1f, 0f, 0f, 0f, 0f, 1f, 0f, 0f, 0f, 0f, 1f, 0f, 0f, 0f, 0f, 1f);

    /// <summary>The second row's vector (M21, M22, M23), the local up.</summary>
    public Vector3 Up
    {
        readonly get => new(M21, M22, M23);
        set => (M21, M22, M23) = (value.X, value.Y, value.Z);
    }

    /// <summary>The opposite of <see cref="Up"/>: (−M21, −M22, −M23).</summary>
    public Vector3 Down
    {
        readonly get => new(-M21, -M22, -M23);
        set => (M21, M22, M23) = (-value.X, -value.Y, -value.Z);
    }

    /// <summary>The first row's vector (M11, M12, M13), the local right.</summary>
    public Vector3 Right
    {
        readonly get => new(M11, M12, M13);
        set => (M11, M12, M13) = (value.X, value.Y, value.Z);
    }

    /// <summary>The opposite of <see cref="Right"/>: (−M11, −M12, −M13).</summary>
    public Vector3 Left
    {
        readonly get => new(-M11, -M12, -M13);
        set => (M11, M12, M13) = (-value.X, -value.Y, -value.Z);
    }

    /// <summary>The local forward, the opposite of the third row: (−M31, −M32, −M33) (XNA is right-handed).</summary>
    public Vector3 Forward
    {
        readonly get => new(-M31, -M32, -M33);
        set => (M31, M32, M33) = (-value.X, -value.Y, -value.Z);
    }

    /// <summary>The third row's vector (M31, M32, M33), the local backward.</summary>
    public Vector3 Backward
    {
        readonly get => new(M31, M32, M33);
        set => (M31, M32, M33) = (value.X, value.Y, value.Z);
    }

    /// <summary>The translation (M41, M42, M43).</summary>
    public Vector3 Translation
    {
        readonly get => new(M41, M42, M43);
        set => (M41, M42, M43) = (value.X, value.Y, value.Z);
    }

    /// <summary>The same matrix as a <see cref="System.Numerics.Matrix4x4"/>.</summary>
    /// <param name="value">The matrix.</param>
    public static implicit operator N.Matrix4x4(Matrix value) => new(
        value.M11, value.M12, value.M13, value.M14, value.M21, value.M22, value.M23, value.M24,
        value.M31, value.M32, value.M33, value.M34, value.M41, value.M42, value.M43, value.M44);

    /// <summary>The same matrix as an XNA <see cref="Matrix"/>.</summary>
    /// <param name="value">The matrix.</param>
    public static implicit operator Matrix(N.Matrix4x4 value) => new(
        value.M11, value.M12, value.M13, value.M14, value.M21, value.M22, value.M23, value.M24,
        value.M31, value.M32, value.M33, value.M34, value.M41, value.M42, value.M43, value.M44);

    /// <summary>A translation.</summary>
    /// <param name="position">The translation.</param>
    /// <returns>The matrix.</returns>
    public static Matrix CreateTranslation(Vector3 position) =>
        new(1f, 0f, 0f, 0f, 0f, 1f, 0f, 0f, 0f, 0f, 1f, 0f, position.X, position.Y, position.Z, 1f);

    /// <summary>The <c>ref</c> form of <see cref="CreateTranslation(Vector3)"/>.</summary>
    /// <param name="position">The translation.</param>
    /// <param name="result">The matrix.</param>
    public static void CreateTranslation(ref Vector3 position, out Matrix result) => result = CreateTranslation(position);

    /// <summary>A translation.</summary>
    /// <param name="xPosition">X translation.</param>
    /// <param name="yPosition">Y translation.</param>
    /// <param name="zPosition">Z translation.</param>
    /// <returns>The matrix.</returns>
    public static Matrix CreateTranslation(float xPosition, float yPosition, float zPosition) =>
        CreateTranslation(new Vector3(xPosition, yPosition, zPosition));

    /// <summary>The <c>ref</c> form of <see cref="CreateTranslation(float, float, float)"/>.</summary>
    /// <param name="xPosition">X translation.</param>
    /// <param name="yPosition">Y translation.</param>
    /// <param name="zPosition">Z translation.</param>
    /// <param name="result">The matrix.</param>
    public static void CreateTranslation(float xPosition, float yPosition, float zPosition, out Matrix result) => result = CreateTranslation(xPosition, yPosition, zPosition);

    /// <summary>A uniform scaling.</summary>
    /// <param name="scale">The factor on every axis.</param>
    /// <returns>The matrix.</returns>
    public static Matrix CreateScale(float scale) =>
        CreateScale(scale, scale, scale);

    /// <summary>The <c>ref</c> form of <see cref="CreateScale(float)"/>.</summary>
    /// <param name="scale">The factor on every axis.</param>
    /// <param name="result">The matrix.</param>
    public static void CreateScale(float scale, out Matrix result) => result = CreateScale(scale);

    /// <summary>A scaling along the axes.</summary>
    /// <param name="xScale">Factor along X.</param>
    /// <param name="yScale">Factor along Y.</param>
    /// <param name="zScale">Factor along Z.</param>
    /// <returns>The matrix.</returns>
    public static Matrix CreateScale(float xScale, float yScale, float zScale) =>
        new(xScale, 0f, 0f, 0f, 0f, yScale, 0f, 0f, 0f, 0f, zScale, 0f, 0f, 0f, 0f, 1f);

    /// <summary>The <c>ref</c> form of <see cref="CreateScale(float, float, float)"/>.</summary>
    /// <param name="xScale">Factor along X.</param>
    /// <param name="yScale">Factor along Y.</param>
    /// <param name="zScale">Factor along Z.</param>
    /// <param name="result">The matrix.</param>
    public static void CreateScale(float xScale, float yScale, float zScale, out Matrix result) => result = CreateScale(xScale, yScale, zScale);

    /// <summary>A scaling along the axes.</summary>
    /// <param name="scales">Factors along X, Y, Z.</param>
    /// <returns>The matrix.</returns>
    public static Matrix CreateScale(Vector3 scales) =>
        CreateScale(scales.X, scales.Y, scales.Z);

    /// <summary>The <c>ref</c> form of <see cref="CreateScale(Vector3)"/>.</summary>
    /// <param name="scales">Factors along X, Y, Z.</param>
    /// <param name="result">The matrix.</param>
    public static void CreateScale(ref Vector3 scales, out Matrix result) => result = CreateScale(scales);

    /// <summary>A rotation about the X axis.</summary>
    /// <param name="radians">Angle, rad (counter-clockwise looking down the axis toward the origin).</param>
    /// <returns>The matrix.</returns>
    public static Matrix CreateRotationX(float radians) =>
        Rotation(radians, 0);

    /// <summary>The <c>ref</c> form of <see cref="CreateRotationX(float)"/>.</summary>
    /// <param name="radians">Angle, rad (counter-clockwise looking down the axis toward the origin).</param>
    /// <param name="result">The matrix.</param>
    public static void CreateRotationX(float radians, out Matrix result) => result = CreateRotationX(radians);

    /// <summary>A rotation about the Y axis.</summary>
    /// <param name="radians">Angle, rad (counter-clockwise looking down the axis toward the origin).</param>
    /// <returns>The matrix.</returns>
    public static Matrix CreateRotationY(float radians) =>
        Rotation(radians, 1);

    /// <summary>The <c>ref</c> form of <see cref="CreateRotationY(float)"/>.</summary>
    /// <param name="radians">Angle, rad (counter-clockwise looking down the axis toward the origin).</param>
    /// <param name="result">The matrix.</param>
    public static void CreateRotationY(float radians, out Matrix result) => result = CreateRotationY(radians);

    /// <summary>A rotation about the Z axis.</summary>
    /// <param name="radians">Angle, rad (counter-clockwise looking down the axis toward the origin).</param>
    /// <returns>The matrix.</returns>
    public static Matrix CreateRotationZ(float radians) =>
        Rotation(radians, 2);

    /// <summary>The <c>ref</c> form of <see cref="CreateRotationZ(float)"/>.</summary>
    /// <param name="radians">Angle, rad (counter-clockwise looking down the axis toward the origin).</param>
    /// <param name="result">The matrix.</param>
    public static void CreateRotationZ(float radians, out Matrix result) => result = CreateRotationZ(radians);

    /// <summary>A rotation about a unit axis.</summary>
    /// <param name="axis">Unit axis.</param>
    /// <param name="angle">Angle, rad.</param>
    /// <returns>The matrix.</returns>
    public static Matrix CreateFromAxisAngle(Vector3 axis, float angle) =>
        N.Matrix4x4.CreateFromAxisAngle(axis, angle);

    /// <summary>The <c>ref</c> form of <see cref="CreateFromAxisAngle(Vector3, float)"/>.</summary>
    /// <param name="axis">Unit axis.</param>
    /// <param name="angle">Angle, rad.</param>
    /// <param name="result">The matrix.</param>
    public static void CreateFromAxisAngle(ref Vector3 axis, float angle, out Matrix result) => result = CreateFromAxisAngle(axis, angle);

    /// <summary>The rotation of a unit quaternion.</summary>
    /// <param name="quaternion">Unit rotation quaternion.</param>
    /// <returns>The matrix.</returns>
    public static Matrix CreateFromQuaternion(Quaternion quaternion) =>
        N.Matrix4x4.CreateFromQuaternion(quaternion);

    /// <summary>The <c>ref</c> form of <see cref="CreateFromQuaternion(Quaternion)"/>.</summary>
    /// <param name="quaternion">Unit rotation quaternion.</param>
    /// <param name="result">The matrix.</param>
    public static void CreateFromQuaternion(ref Quaternion quaternion, out Matrix result) => result = CreateFromQuaternion(quaternion);

    /// <summary>A rotation by roll about Z, then pitch about X, then yaw about Y.</summary>
    /// <param name="yaw">Rotation about Y, rad.</param>
    /// <param name="pitch">Rotation about X, rad.</param>
    /// <param name="roll">Rotation about Z, rad.</param>
    /// <returns>The matrix.</returns>
    public static Matrix CreateFromYawPitchRoll(float yaw, float pitch, float roll) =>
        N.Matrix4x4.CreateFromYawPitchRoll(yaw, pitch, roll);

    /// <summary>The <c>ref</c> form of <see cref="CreateFromYawPitchRoll(float, float, float)"/>.</summary>
    /// <param name="yaw">Rotation about Y, rad.</param>
    /// <param name="pitch">Rotation about X, rad.</param>
    /// <param name="roll">Rotation about Z, rad.</param>
    /// <param name="result">The matrix.</param>
    public static void CreateFromYawPitchRoll(float yaw, float pitch, float roll, out Matrix result) => result = CreateFromYawPitchRoll(yaw, pitch, roll);

    /// <summary>A right-handed view matrix.</summary>
    /// <param name="cameraPosition">Camera position.</param>
    /// <param name="cameraTarget">Point looked at.</param>
    /// <param name="cameraUpVector">Up direction of the camera.</param>
    /// <returns>The matrix.</returns>
    public static Matrix CreateLookAt(Vector3 cameraPosition, Vector3 cameraTarget, Vector3 cameraUpVector) =>
        N.Matrix4x4.CreateLookAt(cameraPosition, cameraTarget, cameraUpVector);

    /// <summary>The <c>ref</c> form of <see cref="CreateLookAt(Vector3, Vector3, Vector3)"/>.</summary>
    /// <param name="cameraPosition">Camera position.</param>
    /// <param name="cameraTarget">Point looked at.</param>
    /// <param name="cameraUpVector">Up direction of the camera.</param>
    /// <param name="result">The matrix.</param>
    public static void CreateLookAt(ref Vector3 cameraPosition, ref Vector3 cameraTarget, ref Vector3 cameraUpVector, out Matrix result) => result = CreateLookAt(cameraPosition, cameraTarget, cameraUpVector);

    /// <summary>A world matrix placing an object at a position facing a direction.</summary>
    /// <param name="position">The translation.</param>
    /// <param name="forward">Forward direction.</param>
    /// <param name="up">Up direction.</param>
    /// <returns>The matrix.</returns>
    public static Matrix CreateWorld(Vector3 position, Vector3 forward, Vector3 up) =>
        N.Matrix4x4.CreateWorld(position, forward, up);

    /// <summary>The <c>ref</c> form of <see cref="CreateWorld(Vector3, Vector3, Vector3)"/>.</summary>
    /// <param name="position">The translation.</param>
    /// <param name="forward">Forward direction.</param>
    /// <param name="up">Up direction.</param>
    /// <param name="result">The matrix.</param>
    public static void CreateWorld(ref Vector3 position, ref Vector3 forward, ref Vector3 up, out Matrix result) => result = CreateWorld(position, forward, up);

    /// <summary>A right-handed perspective projection (throws <see cref="ArgumentOutOfRangeException"/> for invalid values, as XNA).</summary>
    /// <param name="fieldOfView">Vertical field of view, rad, in (0, π).</param>
    /// <param name="aspectRatio">Width / height.</param>
    /// <param name="nearPlaneDistance">Near plane distance (> 0).</param>
    /// <param name="farPlaneDistance">Far plane distance (> near).</param>
    /// <returns>The matrix.</returns>
    public static Matrix CreatePerspectiveFieldOfView(float fieldOfView, float aspectRatio, float nearPlaneDistance, float farPlaneDistance) =>
        N.Matrix4x4.CreatePerspectiveFieldOfView(fieldOfView, aspectRatio, nearPlaneDistance, farPlaneDistance);

    /// <summary>The <c>ref</c> form of <see cref="CreatePerspectiveFieldOfView(float, float, float, float)"/>.</summary>
    /// <param name="fieldOfView">Vertical field of view, rad, in (0, π).</param>
    /// <param name="aspectRatio">Width / height.</param>
    /// <param name="nearPlaneDistance">Near plane distance (> 0).</param>
    /// <param name="farPlaneDistance">Far plane distance (> near).</param>
    /// <param name="result">The matrix.</param>
    public static void CreatePerspectiveFieldOfView(float fieldOfView, float aspectRatio, float nearPlaneDistance, float farPlaneDistance, out Matrix result) => result = CreatePerspectiveFieldOfView(fieldOfView, aspectRatio, nearPlaneDistance, farPlaneDistance);

    /// <summary>A right-handed perspective projection (throws <see cref="ArgumentOutOfRangeException"/> for invalid distances).</summary>
    /// <param name="width">View width at the near plane.</param>
    /// <param name="height">View height at the near plane.</param>
    /// <param name="nearPlaneDistance">Near plane distance (> 0).</param>
    /// <param name="farPlaneDistance">Far plane distance (> near).</param>
    /// <returns>The matrix.</returns>
    public static Matrix CreatePerspective(float width, float height, float nearPlaneDistance, float farPlaneDistance) =>
        N.Matrix4x4.CreatePerspective(width, height, nearPlaneDistance, farPlaneDistance);

    /// <summary>The <c>ref</c> form of <see cref="CreatePerspective(float, float, float, float)"/>.</summary>
    /// <param name="width">View width at the near plane.</param>
    /// <param name="height">View height at the near plane.</param>
    /// <param name="nearPlaneDistance">Near plane distance (> 0).</param>
    /// <param name="farPlaneDistance">Far plane distance (> near).</param>
    /// <param name="result">The matrix.</param>
    public static void CreatePerspective(float width, float height, float nearPlaneDistance, float farPlaneDistance, out Matrix result) => result = CreatePerspective(width, height, nearPlaneDistance, farPlaneDistance);

    /// <summary>A right-handed off-centre perspective projection (throws <see cref="ArgumentOutOfRangeException"/> for invalid distances).</summary>
    /// <param name="left">Minimum X.</param>
    /// <param name="right">Maximum X.</param>
    /// <param name="bottom">Minimum Y.</param>
    /// <param name="top">Maximum Y.</param>
    /// <param name="nearPlaneDistance">Near plane distance (> 0).</param>
    /// <param name="farPlaneDistance">Far plane distance (> near).</param>
    /// <returns>The matrix.</returns>
    public static Matrix CreatePerspectiveOffCenter(float left, float right, float bottom, float top, float nearPlaneDistance, float farPlaneDistance) =>
        N.Matrix4x4.CreatePerspectiveOffCenter(left, right, bottom, top, nearPlaneDistance, farPlaneDistance);

    /// <summary>The <c>ref</c> form of <see cref="CreatePerspectiveOffCenter(float, float, float, float, float, float)"/>.</summary>
    /// <param name="left">Minimum X.</param>
    /// <param name="right">Maximum X.</param>
    /// <param name="bottom">Minimum Y.</param>
    /// <param name="top">Maximum Y.</param>
    /// <param name="nearPlaneDistance">Near plane distance (> 0).</param>
    /// <param name="farPlaneDistance">Far plane distance (> near).</param>
    /// <param name="result">The matrix.</param>
    public static void CreatePerspectiveOffCenter(float left, float right, float bottom, float top, float nearPlaneDistance, float farPlaneDistance, out Matrix result) => result = CreatePerspectiveOffCenter(left, right, bottom, top, nearPlaneDistance, farPlaneDistance);

    /// <summary>A right-handed orthographic projection.</summary>
    /// <param name="width">View width at the near plane.</param>
    /// <param name="height">View height at the near plane.</param>
    /// <param name="zNearPlane">Near Z.</param>
    /// <param name="zFarPlane">Far Z.</param>
    /// <returns>The matrix.</returns>
    public static Matrix CreateOrthographic(float width, float height, float zNearPlane, float zFarPlane) =>
        N.Matrix4x4.CreateOrthographic(width, height, zNearPlane, zFarPlane);

    /// <summary>The <c>ref</c> form of <see cref="CreateOrthographic(float, float, float, float)"/>.</summary>
    /// <param name="width">View width at the near plane.</param>
    /// <param name="height">View height at the near plane.</param>
    /// <param name="zNearPlane">Near Z.</param>
    /// <param name="zFarPlane">Far Z.</param>
    /// <param name="result">The matrix.</param>
    public static void CreateOrthographic(float width, float height, float zNearPlane, float zFarPlane, out Matrix result) => result = CreateOrthographic(width, height, zNearPlane, zFarPlane);

    /// <summary>A right-handed off-centre orthographic projection.</summary>
    /// <param name="left">Minimum X.</param>
    /// <param name="right">Maximum X.</param>
    /// <param name="bottom">Minimum Y.</param>
    /// <param name="top">Maximum Y.</param>
    /// <param name="zNearPlane">Near Z.</param>
    /// <param name="zFarPlane">Far Z.</param>
    /// <returns>The matrix.</returns>
    public static Matrix CreateOrthographicOffCenter(float left, float right, float bottom, float top, float zNearPlane, float zFarPlane) =>
        N.Matrix4x4.CreateOrthographicOffCenter(left, right, bottom, top, zNearPlane, zFarPlane);

    /// <summary>The <c>ref</c> form of <see cref="CreateOrthographicOffCenter(float, float, float, float, float, float)"/>.</summary>
    /// <param name="left">Minimum X.</param>
    /// <param name="right">Maximum X.</param>
    /// <param name="bottom">Minimum Y.</param>
    /// <param name="top">Maximum Y.</param>
    /// <param name="zNearPlane">Near Z.</param>
    /// <param name="zFarPlane">Far Z.</param>
    /// <param name="result">The matrix.</param>
    public static void CreateOrthographicOffCenter(float left, float right, float bottom, float top, float zNearPlane, float zFarPlane, out Matrix result) => result = CreateOrthographicOffCenter(left, right, bottom, top, zNearPlane, zFarPlane);

    /// <summary>A matrix followed by a rotation.</summary>
    /// <param name="value">The matrix.</param>
    /// <param name="rotation">The rotation.</param>
    /// <returns>value·R(rotation).</returns>
    public static Matrix Transform(Matrix value, Quaternion rotation) =>
        value * CreateFromQuaternion(rotation);

    /// <summary>The <c>ref</c> form of <see cref="Transform(Matrix, Quaternion)"/>.</summary>
    /// <param name="value">The matrix.</param>
    /// <param name="rotation">The rotation.</param>
    /// <param name="result">value·R(rotation).</param>
    public static void Transform(ref Matrix value, ref Quaternion rotation, out Matrix result) => result = Transform(value, rotation);

    /// <summary>The transpose.</summary>
    /// <param name="matrix">The matrix.</param>
    /// <returns>Rows and columns swapped.</returns>
    public static Matrix Transpose(Matrix matrix) =>
        new(matrix.M11, matrix.M21, matrix.M31, matrix.M41, matrix.M12, matrix.M22, matrix.M32, matrix.M42, matrix.M13, matrix.M23, matrix.M33, matrix.M43, matrix.M14, matrix.M24, matrix.M34, matrix.M44);

    /// <summary>The <c>ref</c> form of <see cref="Transpose(Matrix)"/>.</summary>
    /// <param name="matrix">The matrix.</param>
    /// <param name="result">Rows and columns swapped.</param>
    public static void Transpose(ref Matrix matrix, out Matrix result) => result = Transpose(matrix);

    /// <summary>The inverse (all entries NaN for a singular matrix).</summary>
    /// <param name="matrix">The matrix.</param>
    /// <returns>M⁻¹.</returns>
    public static Matrix Invert(Matrix matrix) =>
        InvertOrNaN(matrix);

    /// <summary>The <c>ref</c> form of <see cref="Invert(Matrix)"/>.</summary>
    /// <param name="matrix">The matrix.</param>
    /// <param name="result">M⁻¹.</param>
    public static void Invert(ref Matrix matrix, out Matrix result) => result = Invert(matrix);

    /// <summary>Entry-by-entry linear interpolation.</summary>
    /// <param name="matrix1">First matrix.</param>
    /// <param name="matrix2">Second matrix.</param>
    /// <param name="amount">Weight of <paramref name="matrix2"/>.</param>
    /// <returns>matrix1 + (matrix2 − matrix1)·amount.</returns>
    public static Matrix Lerp(Matrix matrix1, Matrix matrix2, float amount) =>
        matrix1 + ((matrix2 - matrix1) * amount);

    /// <summary>The <c>ref</c> form of <see cref="Lerp(Matrix, Matrix, float)"/>.</summary>
    /// <param name="matrix1">First matrix.</param>
    /// <param name="matrix2">Second matrix.</param>
    /// <param name="amount">Weight of <paramref name="matrix2"/>.</param>
    /// <param name="result">matrix1 + (matrix2 − matrix1)·amount.</param>
    public static void Lerp(ref Matrix matrix1, ref Matrix matrix2, float amount, out Matrix result) => result = Lerp(matrix1, matrix2, amount);

    /// <summary>Every entry negated.</summary>
    /// <param name="matrix">The matrix.</param>
    /// <returns>−matrix.</returns>
    public static Matrix Negate(Matrix matrix) =>
        -matrix;

    /// <summary>The <c>ref</c> form of <see cref="Negate(Matrix)"/>.</summary>
    /// <param name="matrix">The matrix.</param>
    /// <param name="result">−matrix.</param>
    public static void Negate(ref Matrix matrix, out Matrix result) => result = Negate(matrix);

    /// <summary>Entry-by-entry sum.</summary>
    /// <param name="matrix1">First matrix.</param>
    /// <param name="matrix2">Second matrix.</param>
    /// <returns>matrix1 + matrix2.</returns>
    public static Matrix Add(Matrix matrix1, Matrix matrix2) =>
        matrix1 + matrix2;

    /// <summary>The <c>ref</c> form of <see cref="Add(Matrix, Matrix)"/>.</summary>
    /// <param name="matrix1">First matrix.</param>
    /// <param name="matrix2">Second matrix.</param>
    /// <param name="result">matrix1 + matrix2.</param>
    public static void Add(ref Matrix matrix1, ref Matrix matrix2, out Matrix result) => result = Add(matrix1, matrix2);

    /// <summary>Entry-by-entry difference.</summary>
    /// <param name="matrix1">First matrix.</param>
    /// <param name="matrix2">Second matrix.</param>
    /// <returns>matrix1 − matrix2.</returns>
    public static Matrix Subtract(Matrix matrix1, Matrix matrix2) =>
        matrix1 - matrix2;

    /// <summary>The <c>ref</c> form of <see cref="Subtract(Matrix, Matrix)"/>.</summary>
    /// <param name="matrix1">First matrix.</param>
    /// <param name="matrix2">Second matrix.</param>
    /// <param name="result">matrix1 − matrix2.</param>
    public static void Subtract(ref Matrix matrix1, ref Matrix matrix2, out Matrix result) => result = Subtract(matrix1, matrix2);

    /// <summary>Matrix product (first <paramref name="matrix1"/>, then <paramref name="matrix2"/>).</summary>
    /// <param name="matrix1">First matrix.</param>
    /// <param name="matrix2">Second matrix.</param>
    /// <returns>matrix1·matrix2.</returns>
    public static Matrix Multiply(Matrix matrix1, Matrix matrix2) =>
        matrix1 * matrix2;

    /// <summary>The <c>ref</c> form of <see cref="Multiply(Matrix, Matrix)"/>.</summary>
    /// <param name="matrix1">First matrix.</param>
    /// <param name="matrix2">Second matrix.</param>
    /// <param name="result">matrix1·matrix2.</param>
    public static void Multiply(ref Matrix matrix1, ref Matrix matrix2, out Matrix result) => result = Multiply(matrix1, matrix2);

    /// <summary>Every entry scaled.</summary>
    /// <param name="matrix1">First matrix.</param>
    /// <param name="scaleFactor">The factor.</param>
    /// <returns>matrix1·scaleFactor.</returns>
    public static Matrix Multiply(Matrix matrix1, float scaleFactor) =>
        matrix1 * scaleFactor;

    /// <summary>The <c>ref</c> form of <see cref="Multiply(Matrix, float)"/>.</summary>
    /// <param name="matrix1">First matrix.</param>
    /// <param name="scaleFactor">The factor.</param>
    /// <param name="result">matrix1·scaleFactor.</param>
    public static void Multiply(ref Matrix matrix1, float scaleFactor, out Matrix result) => result = Multiply(matrix1, scaleFactor);

    /// <summary>Entry-by-entry quotient (as XNA; not a product with an inverse).</summary>
    /// <param name="matrix1">First matrix.</param>
    /// <param name="matrix2">Second matrix.</param>
    /// <returns>matrix1 ./ matrix2.</returns>
    public static Matrix Divide(Matrix matrix1, Matrix matrix2) =>
        matrix1 / matrix2;

    /// <summary>The <c>ref</c> form of <see cref="Divide(Matrix, Matrix)"/>.</summary>
    /// <param name="matrix1">First matrix.</param>
    /// <param name="matrix2">Second matrix.</param>
    /// <param name="result">matrix1 ./ matrix2.</param>
    public static void Divide(ref Matrix matrix1, ref Matrix matrix2, out Matrix result) => result = Divide(matrix1, matrix2);

    /// <summary>Every entry divided.</summary>
    /// <param name="matrix1">First matrix.</param>
    /// <param name="divider">The divisor.</param>
    /// <returns>matrix1 / divider.</returns>
    public static Matrix Divide(Matrix matrix1, float divider) =>
        matrix1 / divider;

    /// <summary>The <c>ref</c> form of <see cref="Divide(Matrix, float)"/>.</summary>
    /// <param name="matrix1">First matrix.</param>
    /// <param name="divider">The divisor.</param>
    /// <param name="result">matrix1 / divider.</param>
    public static void Divide(ref Matrix matrix1, float divider, out Matrix result) => result = Divide(matrix1, divider);

    /// <summary>Entry-by-entry sum.</summary>
    /// <param name="matrix1">First matrix.</param>
    /// <param name="matrix2">Second matrix.</param>
    /// <returns>matrix1 + matrix2.</returns>
    public static Matrix operator +(Matrix matrix1, Matrix matrix2) => Map(matrix1, matrix2, static (a, b) => a + b);

    /// <summary>Entry-by-entry difference.</summary>
    /// <param name="matrix1">First matrix.</param>
    /// <param name="matrix2">Second matrix.</param>
    /// <returns>matrix1 − matrix2.</returns>
    public static Matrix operator -(Matrix matrix1, Matrix matrix2) => Map(matrix1, matrix2, static (a, b) => a - b);

    /// <summary>Every entry negated.</summary>
    /// <param name="matrix1">First matrix.</param>
    /// <returns>−matrix1.</returns>
    public static Matrix operator -(Matrix matrix1) => Map(matrix1, matrix1, static (a, _) => -a);

    /// <summary>Matrix product (first <paramref name="matrix1"/>, then <paramref name="matrix2"/>).</summary>
    /// <param name="matrix1">First matrix.</param>
    /// <param name="matrix2">Second matrix.</param>
    /// <returns>matrix1·matrix2.</returns>
    public static Matrix operator *(Matrix matrix1, Matrix matrix2) => Product(matrix1, matrix2);

    /// <summary>Every entry scaled.</summary>
    /// <param name="matrix">The matrix.</param>
    /// <param name="scaleFactor">The factor.</param>
    /// <returns>matrix·scaleFactor.</returns>
    public static Matrix operator *(Matrix matrix, float scaleFactor) => Map(matrix, matrix, (a, _) => a * scaleFactor);

    /// <summary>Every entry scaled.</summary>
    /// <param name="scaleFactor">The factor.</param>
    /// <param name="matrix">The matrix.</param>
    /// <returns>matrix·scaleFactor.</returns>
    public static Matrix operator *(float scaleFactor, Matrix matrix) => matrix * scaleFactor;

    /// <summary>Entry-by-entry quotient.</summary>
    /// <param name="matrix1">First matrix.</param>
    /// <param name="matrix2">Second matrix.</param>
    /// <returns>matrix1 ./ matrix2.</returns>
    public static Matrix operator /(Matrix matrix1, Matrix matrix2) => Map(matrix1, matrix2, static (a, b) => a / b);

    /// <summary>Every entry divided (multiplied by 1 / divider, as XNA).</summary>
    /// <param name="matrix1">First matrix.</param>
    /// <param name="divider">The divisor.</param>
    /// <returns>matrix1 / divider.</returns>
    public static Matrix operator /(Matrix matrix1, float divider) => matrix1 * (1f / divider);

    /// <summary>Exact equality of all sixteen entries.</summary>
    /// <param name="matrix1">First matrix.</param>
    /// <param name="matrix2">Second matrix.</param>
    /// <returns>True when every entry is equal.</returns>
    public static bool operator ==(Matrix matrix1, Matrix matrix2) => matrix1.Equals(matrix2);

    /// <summary>Inequality of any entry.</summary>
    /// <param name="matrix1">First matrix.</param>
    /// <param name="matrix2">Second matrix.</param>
    /// <returns>True when an entry differs.</returns>
    public static bool operator !=(Matrix matrix1, Matrix matrix2) => !matrix1.Equals(matrix2);

    /// <summary>The determinant.</summary>
    /// <returns>det M.</returns>
    public readonly float Determinant() => ((N.Matrix4x4)this).GetDeterminant();

    /// <summary>Splits an affine matrix into scale, rotation and translation (M = S·R·T).</summary>
    /// <param name="scale">The scale along X, Y, Z.</param>
    /// <param name="rotation">The rotation.</param>
    /// <param name="translation">The translation.</param>
    /// <returns>False when the matrix cannot be split into a rotation (as <see cref="System.Numerics.Matrix4x4.Decompose"/>, which follows XNA).</returns>
    public readonly bool Decompose(out Vector3 scale, out Quaternion rotation, out Vector3 translation)
    {
        bool ok = N.Matrix4x4.Decompose(this, out var s, out var r, out var t);
        scale = s;
        rotation = r;
        translation = t;
        return ok;
    }

    /// <inheritdoc/>
    public readonly bool Equals(Matrix other) =>
        M11 == other.M11 && M12 == other.M12 && M13 == other.M13 && M14 == other.M14
        && M21 == other.M21 && M22 == other.M22 && M23 == other.M23 && M24 == other.M24
        && M31 == other.M31 && M32 == other.M32 && M33 == other.M33 && M34 == other.M34
        && M41 == other.M41 && M42 == other.M42 && M43 == other.M43 && M44 == other.M44;

    /// <inheritdoc/>
    public override readonly bool Equals(object? obj) => obj is Matrix other && Equals(other);

    /// <inheritdoc/>
    public override readonly int GetHashCode() => ((N.Matrix4x4)this).GetHashCode();

    /// <summary>XNA's text form, <c>{ {M11:1 M12:0 M13:0 M14:0} {M21:0 …} … }</c>.</summary>
    /// <returns>The text.</returns>
    public override readonly string ToString() => string.Create(
        CultureInfo.CurrentCulture,
        $"{{ {{M11:{M11} M12:{M12} M13:{M13} M14:{M14}}} {{M21:{M21} M22:{M22} M23:{M23} M24:{M24}}} {{M31:{M31} M32:{M32} M33:{M33} M34:{M34}}} {{M41:{M41} M42:{M42} M43:{M43} M44:{M44}}} }}");

    // Rotation about X (axis 0), Y (1) or Z (2), counter-clockwise looking from the positive axis toward the origin.
    private static Matrix Rotation(float radians, int axis)
    {
        float c = MathF.Cos(radians), s = MathF.Sin(radians);
        var m = Identity;
        switch (axis)
        {
            case 0:
                (m.M22, m.M23, m.M32, m.M33) = (c, s, -s, c);
                break;
            case 1:
                (m.M11, m.M13, m.M31, m.M33) = (c, -s, s, c);
                break;
            default:
                (m.M11, m.M12, m.M21, m.M22) = (c, s, -s, c);
                break;
        }

        return m;
    }

    private static Matrix InvertOrNaN(Matrix matrix) =>
        N.Matrix4x4.Invert(matrix, out var inverse) ? inverse : Map(default, default, static (_, _) => float.NaN);

    private static Matrix Product(Matrix a, Matrix b)
    {
        Matrix r;
        r.M11 = (a.M11 * b.M11) + (a.M12 * b.M21) + (a.M13 * b.M31) + (a.M14 * b.M41);
        r.M12 = (a.M11 * b.M12) + (a.M12 * b.M22) + (a.M13 * b.M32) + (a.M14 * b.M42);
        r.M13 = (a.M11 * b.M13) + (a.M12 * b.M23) + (a.M13 * b.M33) + (a.M14 * b.M43);
        r.M14 = (a.M11 * b.M14) + (a.M12 * b.M24) + (a.M13 * b.M34) + (a.M14 * b.M44);
        r.M21 = (a.M21 * b.M11) + (a.M22 * b.M21) + (a.M23 * b.M31) + (a.M24 * b.M41);
        r.M22 = (a.M21 * b.M12) + (a.M22 * b.M22) + (a.M23 * b.M32) + (a.M24 * b.M42);
        r.M23 = (a.M21 * b.M13) + (a.M22 * b.M23) + (a.M23 * b.M33) + (a.M24 * b.M43);
        r.M24 = (a.M21 * b.M14) + (a.M22 * b.M24) + (a.M23 * b.M34) + (a.M24 * b.M44);
        r.M31 = (a.M31 * b.M11) + (a.M32 * b.M21) + (a.M33 * b.M31) + (a.M34 * b.M41);
        r.M32 = (a.M31 * b.M12) + (a.M32 * b.M22) + (a.M33 * b.M32) + (a.M34 * b.M42);
        r.M33 = (a.M31 * b.M13) + (a.M32 * b.M23) + (a.M33 * b.M33) + (a.M34 * b.M43);
        r.M34 = (a.M31 * b.M14) + (a.M32 * b.M24) + (a.M33 * b.M34) + (a.M34 * b.M44);
        r.M41 = (a.M41 * b.M11) + (a.M42 * b.M21) + (a.M43 * b.M31) + (a.M44 * b.M41);
        r.M42 = (a.M41 * b.M12) + (a.M42 * b.M22) + (a.M43 * b.M32) + (a.M44 * b.M42);
        r.M43 = (a.M41 * b.M13) + (a.M42 * b.M23) + (a.M43 * b.M33) + (a.M44 * b.M43);
        r.M44 = (a.M41 * b.M14) + (a.M42 * b.M24) + (a.M43 * b.M34) + (a.M44 * b.M44);
        return r;
    }

    private static Matrix Map(Matrix a, Matrix b, Func<float, float, float> f) => new(
        f(a.M11, b.M11), f(a.M12, b.M12), f(a.M13, b.M13), f(a.M14, b.M14),
        f(a.M21, b.M21), f(a.M22, b.M22), f(a.M23, b.M23), f(a.M24, b.M24),
        f(a.M31, b.M31), f(a.M32, b.M32), f(a.M33, b.M33), f(a.M34, b.M34),
        f(a.M41, b.M41), f(a.M42, b.M42), f(a.M43, b.M43), f(a.M44, b.M44));
}
