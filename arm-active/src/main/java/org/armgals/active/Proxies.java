package org.armgals.active;

import java.lang.reflect.InvocationHandler;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.lang.reflect.Proxy;
import org.jspecify.annotations.Nullable;

/** Typed interface proxies over an active object (see {@link ActiveRef#proxy}). */
final class Proxies {
  private Proxies() {}

  static <I> I create(ActiveRef<?> ref, Object servant, Class<I> type) {
    java.util.Objects.requireNonNull(type, "type");
    if (!type.isInterface()) {
      throw new IllegalArgumentException("proxy type must be an interface, was " + type.getName());
    }
    if (!java.lang.reflect.Modifier.isPublic(type.getModifiers())
        && !type.getPackageName().equals(Proxies.class.getPackageName())) {
      throw new IllegalArgumentException(
          "proxy interface "
              + type.getName()
              + " must be public: the runtime calls its methods from package "
              + Proxies.class.getPackageName());
    }
    if (!type.isInstance(servant)) {
      throw new IllegalArgumentException(
          "servant " + servant.getClass().getName() + " does not implement " + type.getName());
    }
    for (Method m : type.getMethods()) {
      Class<?> r = m.getReturnType();
      if (r != void.class && r != Future.class && r != FutureValue.class) {
        throw new IllegalArgumentException(
            "method "
                + type.getSimpleName()
                + "."
                + m.getName()
                + " returns "
                + r.getName()
                + "; a proxy method must return void, Future or FutureValue");
      }
    }
    @SuppressWarnings("unchecked")
    ActiveRef<Object> target = (ActiveRef<Object>) ref;
    InvocationHandler handler = new Handler(target, type);
    return type.cast(Proxy.newProxyInstance(type.getClassLoader(), new Class<?>[] {type}, handler));
  }

  private record Handler(ActiveRef<Object> target, Class<?> type) implements InvocationHandler {
    @Override
    public @Nullable Object invoke(Object proxy, Method method, @Nullable Object[] args) {
      if (method.getDeclaringClass() == Object.class) {
        return switch (method.getName()) {
          case "equals" -> args != null && proxy == args[0];
          case "hashCode" -> System.identityHashCode(proxy);
          default -> type.getSimpleName() + "Proxy[" + target.address() + "]";
        };
      }
      Class<?> r = method.getReturnType();
      if (r == void.class) {
        target.send(s -> call(method, s, args));
        return null;
      }
      if (r == Future.class) {
        return target.call(
            s -> {
              Object f = call(method, s, args);
              if (f instanceof Future fut) {
                fut.touch();
              }
              return null;
            });
      }
      return target.call(
          s -> {
            Object f = call(method, s, args);
            return f instanceof FutureValue<?> fv ? fv.getValue() : null;
          });
    }

    private static @Nullable Object call(Method m, Object servant, @Nullable Object[] args)
        throws Exception {
      try {
        return m.invoke(servant, args);
      } catch (InvocationTargetException e) {
        Throwable cause = e.getCause();
        if (cause instanceof Exception ex) {
          throw ex;
        }
        if (cause instanceof Error err) {
          throw err;
        }
        throw e;
      }
    }
  }
}
