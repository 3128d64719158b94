using System;
using System.Linq;
using System.Reflection;
using System.Text;

namespace URWPGSim2D.Tests.OldStrategies;

/// <summary>
/// Writes (in C# 3, as the original's teams wrote) a class <c>OldApi.Toucher</c> whose method
/// <c>Touch(bool)</c> refers to every type and member the stand-ins declare (<see cref="OriginalApiStubs"/>):
/// reads and writes each field and property, calls each method, operator and constructor. Compiling
/// the method for this runtime binds every reference, so one DLL checks the whole surface.
/// </summary>
internal static class ApiToucher
{
    /// <summary>The number of members the toucher refers to.</summary>
    public static int Members => OriginalApiStubs.Types().Sum(t => OriginalApiStubs.Members(t).Count(m => m is not ConstructorInfo || !t.IsAbstract));

    /// <summary>The toucher's source.</summary>
    public static string Source()
    {
        var s = new StringBuilder("namespace OldApi {\npublic static class Toucher {\npublic static int Touch(bool run) {\nif (!run) return 0;\nint n = 0;\nobject o;\n");
        int local = 0;
        foreach (var definition in OriginalApiStubs.Types())
        {
            var type = definition.IsGenericTypeDefinition
                ? definition.MakeGenericType(definition.GetGenericArguments().Select(g => g.GetGenericParameterConstraints().FirstOrDefault(c => !c.IsInterface) ?? typeof(object)).ToArray())
                : definition;
            string t = OriginalApiStubs.Name(type);
            s.Append("o = typeof(").Append(t).Append("); n++;\n");
            if (definition.IsEnum)
            {
                continue;
            }

            string instance = "i" + local++;
            s.Append(definition.IsAbstract && definition.IsSealed ? "// static " : string.Empty).Append(t).Append(' ').Append(instance).Append(" = default(").Append(t).Append(");\n");
            foreach (var member in OriginalApiStubs.Members(definition))
            {
                string target = IsStatic(member) ? t : instance;
                switch (member)
                {
                    case FieldInfo f when f.IsLiteral:
                        s.Append("o = ").Append(target).Append('.').Append(f.Name).Append(";\n");
                        break;
                    case FieldInfo f:
                        s.Append("o = ").Append(target).Append('.').Append(f.Name).Append(";\n");
                        if (!f.IsInitOnly)
                        {
                            s.Append(target).Append('.').Append(f.Name).Append(" = default(").Append(Closed(f.FieldType, type)).Append(");\n");
                        }

                        break;
                    case PropertyInfo p:
                        var index = p.GetIndexParameters();
                        string access = index.Length == 0 ? target + "." + p.Name : target + "[" + string.Join(", ", index.Select(i => "default(" + Closed(i.ParameterType, type) + ")")) + "]";
                        if (p.GetMethod is { IsPublic: true })
                        {
                            s.Append("o = ").Append(access).Append(";\n");
                        }

                        if (p.SetMethod is { IsPublic: true })
                        {
                            s.Append(access).Append(" = default(").Append(Closed(p.PropertyType, type)).Append(");\n");
                        }

                        break;
                    case MethodInfo m when m.IsSpecialName:
                        var operands = m.GetParameters().Select(p => "default(" + Closed(p.ParameterType, type) + ")").ToArray();
                        string op = Operator(m.Name);
                        s.Append("o = ").Append(operands.Length == 1 ? op + operands[0] : operands[0] + " " + op + " " + operands[1]).Append(";\n");
                        break;
                    case MethodInfo m:
                        s.Append(Arguments(m, type, ref local, out string args));
                        s.Append(m.ReturnType == typeof(void) ? string.Empty : "o = ").Append(target).Append('.').Append(m.Name).Append('(').Append(args).Append(");\n");
                        break;
                    case ConstructorInfo c when !definition.IsAbstract:
                        s.Append(Arguments(c, type, ref local, out string cargs));
                        s.Append("o = new ").Append(t).Append('(').Append(cargs).Append(");\n");
                        break;
                    default:
                        continue;
                }

                s.Append("n++;\n");
            }
        }

        s.Append("return n;\n}\n}\n}\n");
        return s.ToString();
    }

    private static string Arguments(MethodBase method, Type owner, ref int local, out string args)
    {
        var declarations = new StringBuilder();
        var list = new System.Collections.Generic.List<string>();
        foreach (var p in method.GetParameters())
        {
            string type = Closed(p.ParameterType, owner);
            if (p.ParameterType.IsByRef)
            {
                string name = "a" + local++;
                declarations.Append(type).Append(' ').Append(name).Append(" = default(").Append(type).Append(");\n");
                list.Add((p.IsOut ? "out " : "ref ") + name);
            }
            else
            {
                list.Add("default(" + type + ")");
            }
        }

        args = string.Join(", ", list);
        return declarations.ToString();
    }

    private static string Closed(Type type, Type owner)
    {
        if (type.IsByRef)
        {
            return Closed(type.GetElementType()!, owner);
        }

        return OriginalApiStubs.Name(Substitute(type, owner));
    }

    private static Type Substitute(Type type, Type owner)
    {
        if (type.IsGenericParameter && owner.IsConstructedGenericType)
        {
            return owner.GetGenericArguments()[type.GenericParameterPosition];
        }

        if (type.IsArray)
        {
            var element = Substitute(type.GetElementType()!, owner);
            return type.GetArrayRank() == 1 ? element.MakeArrayType() : element.MakeArrayType(type.GetArrayRank());
        }

        return type.IsGenericType && type.ContainsGenericParameters
            ? type.GetGenericTypeDefinition().MakeGenericType(type.GetGenericArguments().Select(a => Substitute(a, owner)).ToArray())
            : type;
    }

    private static bool IsStatic(MemberInfo member) => member switch
    {
        FieldInfo f => f.IsStatic,
        PropertyInfo p => (p.GetMethod ?? p.SetMethod)!.IsStatic,
        MethodBase m => m.IsStatic,
        _ => false,
    };

    private static string Operator(string name) => name switch
    {
        "op_Addition" or "op_UnaryPlus" => "+",
        "op_Subtraction" or "op_UnaryNegation" => "-",
        "op_Multiply" => "*",
        "op_Division" => "/",
        "op_Equality" => "==",
        _ => "!=",
    };
}
