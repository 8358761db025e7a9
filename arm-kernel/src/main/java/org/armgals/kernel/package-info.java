/**
 * The ARM kernel (paper §3, §4.2): entities, structural meta-entities, behavioral meta-entities and
 * the events between them.
 *
 * <p>{@link org.armgals.kernel.StructuralMeta#bootstrap} builds the kernel as in ObjVlisp: {@code
 * StructuralMeta} is its own instance; {@code Entity}, {@code StructuralMeta} and {@code
 * BehavioralMeta} are structural meta-entities; {@code basicBehavioralMeta} is an instance of
 * {@code BehavioralMeta} and the behavioral meta of all kernel entities, itself included. Every
 * entity is an active object of arm-active (by composition: its servant runs the entity's
 * activation), so the five flows of §3.1 are asynchronous events:
 *
 * <ol>
 *   <li>notifications, base to behavioral meta: {@link org.armgals.kernel.Notification};
 *   <li>reflective requests, base to behavioral meta: {@link org.armgals.kernel.ReflectiveRequest};
 *   <li>adaptation requests, behavioral meta to base: {@link org.armgals.kernel.AdaptationRequest},
 *       acknowledged by {@link org.armgals.kernel.AdaptationAck};
 *   <li>structural modifications, behavioral meta to structural meta: {@link
 *       org.armgals.kernel.StructuralMeta#addBehavior} and {@link
 *       org.armgals.kernel.StructuralMeta#deleteBehavior};
 *   <li>harmonization, structural meta to its instances.
 * </ol>
 */
@NullMarked
package org.armgals.kernel;

import org.jspecify.annotations.NullMarked;
