using System;
using System.Collections.Generic;
using System.Linq;
using System.Reflection;
using System.Text;

namespace URWPGSim2D.Tests.OldStrategies;

/// <summary>
/// Writes the sources of stand-ins for the original's assemblies (<c>URWPGSim2D.Common</c>, <c>.Core</c>,
/// <c>.StrategyLoader</c>, <c>.StrategyHelper</c>, <c>Microsoft.Xna.Framework</c>) from the public surface
/// of the compatibility assembly: each type goes to the assembly its namespace belonged to in the original,
/// with every public field, property, method, operator and constructor (bodies empty), against the
/// .NET Framework 2.0 stubs (<see cref="FrameworkStubs"/>). Members that use types the original never had
/// (System.Numerics, spans, the SDK) are left out. Also writes a class that refers to every member, so one
/// compiled DLL touches the whole surface.
/// </summary>
internal static class OriginalApiStubs
{
    /// <summary>The original's assemblies in the order they can be compiled (each uses only earlier ones).</summary>
    public static readonly (string Assembly, string Namespace)[] Assemblies =
    [
        ("Microsoft.Xna.Framework", "Microsoft.Xna.Framework"),
        ("URWPGSim2D.Common", "URWPGSim2D.Common"),
        ("URWPGSim2D.Core", "URWPGSim2D.Core"),
        ("URWPGSim2D.StrategyLoader", "URWPGSim2D.StrategyLoader"),
        ("URWPGSim2D.StrategyHelper", "URWPGSim2D.StrategyHelper"),
    ];

    private static readonly Dictionary<Type, string> Keywords = new()
    {
        [typeof(void)] = "void", [typeof(bool)] = "bool", [typeof(byte)] = "byte", [typeof(int)] = "int",
        [typeof(long)] = "long", [typeof(float)] = "float", [typeof(double)] = "double", [typeof(string)] = "string",
        [typeof(object)] = "object", [typeof(char)] = "char", [typeof(short)] = "short",
    };

    private static readonly Dictionary<string, string> Operators = new()
    {
        ["op_Addition"] = "+", ["op_Subtraction"] = "-", ["op_Multiply"] = "*", ["op_Division"] = "/",
        ["op_UnaryNegation"] = "-", ["op_UnaryPlus"] = "+", ["op_Equality"] = "==", ["op_Inequality"] = "!=",
    };

    private static readonly HashSet<Type> Framework =
    [
        typeof(System.Collections.Hashtable), typeof(System.Drawing.Color), typeof(System.Drawing.Point), typeof(System.Drawing.Rectangle),
        typeof(List<>), typeof(ICloneable), typeof(MarshalByRefObject),
    ];

    /// <summary>The public types of the compatibility assembly in the original's namespaces.</summary>
    public static IEnumerable<Type> Types() =>
        typeof(Compat.Retargeting.OriginalReferences).Assembly.GetExportedTypes()
            .Where(t => Assemblies.Any(a => a.Namespace == t.Namespace))
            .OrderBy(t => t.FullName, StringComparer.Ordinal);

    /// <summary>The source of the stand-in for <paramref name="assembly"/>, with the original's version (XNA's: 3.1.0.0).</summary>
    public static string Source(string assembly)
    {
        string ns = Assemblies.Single(a => a.Assembly == assembly).Namespace;
        string version = ns == "Microsoft.Xna.Framework" ? "3.1.0.0" : "1.2.123.20110";
        var s = new StringBuilder("[assembly: System.Reflection.AssemblyVersion(\"" + version + "\")]\n");
        foreach (var type in Types().Where(t => t.Namespace == ns))
        {
            s.Append("namespace ").Append(ns).Append(" {\n");
            Declare(type, s);
            s.Append("}\n");
        }

        return s.ToString();
    }

    /// <summary>Whether a member's signature uses only types the original had.</summary>
    public static bool Original(Type type)
    {
        if (type.IsByRef || type.IsArray)
        {
            return Original(type.GetElementType()!);
        }

        if (type.IsGenericParameter || Keywords.ContainsKey(type))
        {
            return true;
        }

        if (type.IsGenericType)
        {
            var definition = type.GetGenericTypeDefinition();
            return (Framework.Contains(definition) || IsOriginalApi(definition)) && type.GetGenericArguments().All(Original);
        }

        return Framework.Contains(type) || IsOriginalApi(type);
    }

    /// <summary>The public fields, properties, methods and constructors of <paramref name="type"/> that the stand-ins declare.</summary>
    public static IEnumerable<MemberInfo> Members(Type type)
    {
        const BindingFlags Flags = BindingFlags.Public | BindingFlags.Instance | BindingFlags.Static | BindingFlags.DeclaredOnly;
        foreach (var f in type.GetFields(Flags).Where(f => !type.IsEnum || f.IsStatic).Where(f => Original(f.FieldType)))
        {
            yield return f;
        }

        foreach (var p in type.GetProperties(Flags).Where(p => Original(p.PropertyType) && p.GetIndexParameters().All(i => Original(i.ParameterType))))
        {
            yield return p;
        }

        foreach (var m in type.GetMethods(Flags).Where(m => !m.IsSpecialName || Operators.ContainsKey(m.Name)))
        {
            if (Original(m.ReturnType) && m.GetParameters().All(p => Original(p.ParameterType)) && m.GetBaseDefinition().DeclaringType == type)
            {
                yield return m;
            }
        }

        foreach (var c in type.GetConstructors(BindingFlags.Public | BindingFlags.Instance).Where(c => c.GetParameters().All(p => Original(p.ParameterType))))
        {
            yield return c;
        }
    }

    /// <summary>The C# name of <paramref name="type"/>.</summary>
    public static string Name(Type type)
    {
        if (Keywords.TryGetValue(type, out string? keyword))
        {
            return keyword;
        }

        if (type.IsByRef)
        {
            return Name(type.GetElementType()!);
        }

        if (type.IsArray)
        {
            return Name(type.GetElementType()!) + "[" + new string(',', type.GetArrayRank() - 1) + "]";
        }

        if (type.IsGenericParameter)
        {
            return type.Name;
        }

        string name = "global::" + type.Namespace + "." + (type.IsGenericType ? type.Name[..type.Name.IndexOf('`')] : type.Name);
        return type.IsGenericType ? name + "<" + string.Join(", ", type.GetGenericArguments().Select(Name)) + ">" : name;
    }

    private static bool IsOriginalApi(Type type) => type.Assembly == typeof(Compat.Retargeting.OriginalReferences).Assembly
        && Assemblies.Any(a => a.Namespace == type.Namespace);

    private static void Declare(Type type, StringBuilder s)
    {
        string name = type.IsGenericType ? type.Name[..type.Name.IndexOf('`')] + "<" + string.Join(", ", type.GetGenericArguments().Select(a => a.Name)) + ">" : type.Name;
        if (type.IsEnum)
        {
            s.Append("public enum ").Append(type.Name).Append(" : ").Append(Name(Enum.GetUnderlyingType(type))).Append(" {");
            foreach (var f in type.GetFields(BindingFlags.Public | BindingFlags.Static))
            {
                s.Append(f.Name).Append(" = ").Append(Convert.ToInt64(f.GetRawConstantValue(), System.Globalization.CultureInfo.InvariantCulture)).Append(", ");
            }

            s.Append("}\n");
            return;
        }

        if (type.IsInterface)
        {
            s.Append("public interface ").Append(name).Append(" {\n");
            foreach (var m in type.GetMethods())
            {
                s.Append(Name(m.ReturnType)).Append(' ').Append(m.Name).Append('(').Append(Parameters(m)).Append(");\n");
            }

            s.Append("}\n");
            return;
        }

        string kind = type.IsValueType ? "struct" : (type.IsAbstract && type.IsSealed ? "static class" : type.IsAbstract ? "abstract class" : "class");
        s.Append("public ").Append(kind).Append(' ').Append(name);
        var bases = new List<string>();
        if (type.BaseType is { } b && b != typeof(object) && b != typeof(ValueType) && Original(b))
        {
            bases.Add(Name(b));
        }

        bases.AddRange(type.GetInterfaces().Where(i => IsOriginalApi(i) || i == typeof(ICloneable)).Select(Name));
        if (bases.Count > 0)
        {
            s.Append(" : ").Append(string.Join(", ", bases));
        }

        foreach (var g in type.IsGenericTypeDefinition ? type.GetGenericArguments() : [])
        {
            var constraints = g.GetGenericParameterConstraints().Select(Name).ToList();
            if ((g.GenericParameterAttributes & GenericParameterAttributes.DefaultConstructorConstraint) != 0)
            {
                constraints.Add("new()");
            }

            if (constraints.Count > 0)
            {
                s.Append(" where ").Append(g.Name).Append(" : ").Append(string.Join(", ", constraints));
            }
        }

        s.Append(" {\n");
        if (!type.IsValueType && !(type.IsAbstract && type.IsSealed) && type.GetConstructor(Type.EmptyTypes) is null)
        {
            s.Append("internal ").Append(type.Name.Split('`')[0]).Append("() { }\n");
        }

        foreach (var member in Members(type))
        {
            Declare(type, member, s);
        }

        s.Append("}\n");
    }

    private static void Declare(Type type, MemberInfo member, StringBuilder s)
    {
        string simple = type.Name.Split('`')[0];
        switch (member)
        {
            case FieldInfo f when f.IsLiteral:
                s.Append("public const ").Append(Name(f.FieldType)).Append(' ').Append(f.Name).Append(" = ")
                    .Append(Literal(f.GetRawConstantValue())).Append(";\n");
                break;
            case FieldInfo f:
                s.Append("public ").Append(f.IsStatic ? "static " : string.Empty).Append(f.IsInitOnly ? "readonly " : string.Empty)
                    .Append(Name(f.FieldType)).Append(' ').Append(f.Name).Append(";\n");
                break;
            case PropertyInfo p:
                bool isStatic = (p.GetMethod ?? p.SetMethod)!.IsStatic;
                var index = p.GetIndexParameters();
                s.Append("public ").Append(isStatic ? "static " : string.Empty).Append(Name(p.PropertyType)).Append(' ')
                    .Append(index.Length == 0 ? p.Name : "this[" + Parameters(index) + "]").Append(" { ");
                if (p.GetMethod is { IsPublic: true })
                {
                    s.Append("get { throw null; } ");
                }

                if (p.SetMethod is { IsPublic: true })
                {
                    s.Append("set { } ");
                }

                s.Append("}\n");
                break;
            case MethodInfo m when Operators.TryGetValue(m.Name, out string? op):
                s.Append("public static ").Append(Name(m.ReturnType)).Append(" operator ").Append(op).Append('(').Append(Parameters(m)).Append(") { throw null; }\n");
                break;
            case MethodInfo m:
                s.Append("public ").Append(m.IsStatic ? "static " : m.IsVirtual && !m.IsFinal ? "virtual " : string.Empty).Append(Name(m.ReturnType)).Append(' ')
                    .Append(m.Name).Append('(').Append(Parameters(m)).Append(") { ")
                    .Append(string.Concat(m.GetParameters().Where(p => p.IsOut).Select(p => p.Name + " = default(" + Name(p.ParameterType) + "); ")))
                    .Append("throw null; }\n");
                break;
            case ConstructorInfo c:
                s.Append("public ").Append(simple).Append('(').Append(Parameters(c)).Append(") { ")
                    .Append(type.IsValueType ? "this = default(" + simple + "); " : string.Empty).Append("}\n");
                break;
        }
    }

    private static string Parameters(MethodBase method) => Parameters(method.GetParameters());

    private static string Parameters(ParameterInfo[] parameters) => string.Join(", ", parameters.Select(p =>
        (p.ParameterType.IsByRef ? (p.IsOut ? "out " : "ref ") : string.Empty) + Name(p.ParameterType) + " " + p.Name));

    private static string Literal(object? value) => value switch
    {
        float f => f.ToString("R", System.Globalization.CultureInfo.InvariantCulture) + "f",
        double d => d.ToString("R", System.Globalization.CultureInfo.InvariantCulture),
        string str => "\"" + str + "\"",
        bool b => b ? "true" : "false",
        _ => Convert.ToString(value, System.Globalization.CultureInfo.InvariantCulture)!,
    };
}
